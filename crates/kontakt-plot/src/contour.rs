//! Boundary of the region `values > 0` of a cell-centred field (marching squares).

/// Sentinel for "no neighbour" in the edge adjacency table.
const NONE: usize = usize::MAX;

/// The padded node grid: the cell centres of the field plus a ring of zero-valued nodes
/// around it, so that every boundary curve is closed, even where the region touches the edge
/// of the grid.
struct Padded<'a> {
    nx: usize,
    ny: usize,
    x_min: f64,
    y_min: f64,
    dx: f64,
    dy: f64,
    values: &'a [f64],
}

impl Padded<'_> {
    /// Number of nodes along x and y, padding included.
    fn dims(&self) -> (usize, usize) {
        (self.nx + 2, self.ny + 2)
    }

    /// Value at padded node (i, j); the padding ring is 0.
    fn value(&self, i: usize, j: usize) -> f64 {
        if i == 0 || j == 0 || i > self.nx || j > self.ny {
            0.0
        } else {
            self.values
                .get((j - 1) * self.nx + (i - 1))
                .copied()
                .unwrap_or(0.0)
        }
    }

    fn is_padding(&self, i: usize, j: usize) -> bool {
        i == 0 || j == 0 || i > self.nx || j > self.ny
    }

    /// Position of padded node (i, j) in mm.
    fn position(&self, i: usize, j: usize) -> (f64, f64) {
        (
            self.x_min + (i as f64 - 0.5) * self.dx,
            self.y_min + (j as f64 - 0.5) * self.dy,
        )
    }

    /// Where the boundary crosses the grid edge from node `a` (inside) to node `b` (outside),
    /// as the fraction of the way from `a` to `b`.
    ///
    /// * If the outside value is negative, the field is a genuine level-set function: linear
    ///   interpolation of the 0 level.
    /// * Otherwise the field vanishes outside (a contact pressure). Pressure at the edge of a
    ///   contact between smooth bodies behaves like the square root of the distance to the
    ///   edge, so p² is extrapolated linearly from the inside node and the next node further
    ///   in along the same grid line (exact for a Hertz field up to the curvature of the
    ///   ellipse). Without a usable inner neighbour the midpoint is taken.
    ///
    /// The result is kept strictly between the two nodes, and within the grid (at most half
    /// way) when `b` is a padding node.
    fn crossing(&self, a: (usize, usize), b: (usize, usize)) -> f64 {
        let va = self.value(a.0, a.1);
        let vb = self.value(b.0, b.1);
        let t = if vb < 0.0 {
            va / (va - vb)
        } else {
            // Inner neighbour a' = a - (b - a); a is never padding, so this stays in range.
            let inner = ((2 * a.0).checked_sub(b.0), (2 * a.1).checked_sub(b.1));
            match inner {
                (Some(i), Some(j)) if !self.is_padding(i, j) && self.value(i, j) > 0.0 => {
                    let qa = va * va;
                    let vi = self.value(i, j);
                    let qi = vi * vi;
                    if qi > qa && (qi - qa).is_finite() {
                        qa / (qi - qa)
                    } else {
                        0.5
                    }
                }
                _ => 0.5,
            }
        };
        let t = if t.is_finite() { t } else { 0.5 };
        let hi = if self.is_padding(b.0, b.1) { 0.5 } else { 0.95 };
        t.clamp(0.05, hi)
    }
}

/// Closed polylines (in mm) of the boundary of the region `values > 0` of a field on a
/// uniform cell-centred grid.
///
/// The grid is the one of [`FieldMap`](crate::FieldMap): value `(i, j)` sits at
/// `x = x_min + (i + 0.5) dx`, `y = y_min + (j + 0.5) dy` and is stored at index `j*nx + i`.
/// The boundary is found by marching squares between the cell centres, with the field taken
/// as 0 outside the grid, so every curve is closed; each returned polyline ends with a copy of
/// its first point. Saddle cells are resolved with the mean of their four corners. Where the
/// field vanishes outside the region (a contact pressure), the crossing on each grid edge is
/// placed by extrapolating p² inwards (exact for the square-root edge of a Hertz pressure),
/// which keeps the curve within a fraction of a cell of the true contact edge.
///
/// One polyline per connected boundary: two separate contact patches give two, a patch with a
/// hole gives two as well. Non-finite values count as "outside". Returns an empty list if the
/// region is empty, if `nx` or `ny` is 0, or if `values.len() != nx*ny`.
pub fn contour_zero(
    nx: usize,
    ny: usize,
    x_min: f64,
    y_min: f64,
    dx: f64,
    dy: f64,
    values: &[f64],
) -> Vec<Vec<(f64, f64)>> {
    if nx == 0 || ny == 0 || nx.checked_mul(ny) != Some(values.len()) {
        return Vec::new();
    }
    let grid = Padded {
        nx,
        ny,
        x_min,
        y_min,
        dx,
        dy,
        values,
    };
    let (gx, gy) = grid.dims();
    // Edge numbering: horizontal edge (i,j)-(i+1,j) -> j*(gx-1) + i;
    // vertical edge (i,j)-(i,j+1) -> n_h + j*gx + i.
    let n_h = (gx - 1) * gy;
    let n_v = gx * (gy - 1);
    let h_edge = |i: usize, j: usize| j * (gx - 1) + i;
    let v_edge = |i: usize, j: usize| n_h + j * gx + i;
    let inside = |i: usize, j: usize| grid.value(i, j) > 0.0;

    let mut adj = vec![[NONE; 2]; n_h + n_v];
    let mut link = |a: usize, b: usize| {
        for (e, other) in [(a, b), (b, a)] {
            if let Some(slot) = adj.get_mut(e) {
                if slot[0] == NONE {
                    slot[0] = other;
                } else if slot[1] == NONE {
                    slot[1] = other;
                }
            }
        }
    };

    for j in 0..gy - 1 {
        for i in 0..gx - 1 {
            // Corners: c0 (i,j), c1 (i+1,j), c2 (i+1,j+1), c3 (i,j+1).
            let c = [
                inside(i, j),
                inside(i + 1, j),
                inside(i + 1, j + 1),
                inside(i, j + 1),
            ];
            let case = usize::from(c[0])
                | usize::from(c[1]) << 1
                | usize::from(c[2]) << 2
                | usize::from(c[3]) << 3;
            // Edges: e0 bottom, e1 right, e2 top, e3 left.
            let e = [
                h_edge(i, j),
                v_edge(i + 1, j),
                h_edge(i, j + 1),
                v_edge(i, j),
            ];
            match case {
                0 | 15 => {}
                5 | 10 => {
                    let mean = (grid.value(i, j)
                        + grid.value(i + 1, j)
                        + grid.value(i + 1, j + 1)
                        + grid.value(i, j + 1))
                        / 4.0;
                    // Cut off the corners that are of the other kind than the centre.
                    let centre_inside = mean > 0.0;
                    let cut_c0_c2 = (case == 5) != centre_inside;
                    if cut_c0_c2 {
                        link(e[0], e[3]);
                        link(e[1], e[2]);
                    } else {
                        link(e[0], e[1]);
                        link(e[2], e[3]);
                    }
                }
                _ => {
                    // Exactly two crossing edges.
                    let crossing: Vec<usize> = (0..4)
                        .filter(|&k| {
                            let (p, q) = match k {
                                0 => (0, 1),
                                1 => (1, 2),
                                2 => (3, 2),
                                _ => (0, 3),
                            };
                            c[p] != c[q]
                        })
                        .map(|k| e[k])
                        .collect();
                    if let [a, b] = crossing[..] {
                        link(a, b);
                    }
                }
            }
        }
    }

    // Crossing point of an edge.
    let point = |edge: usize| -> (f64, f64) {
        let (a, b) = if edge < n_h {
            let (i, j) = (edge % (gx - 1), edge / (gx - 1));
            ((i, j), (i + 1, j))
        } else {
            let k = edge - n_h;
            let (i, j) = (k % gx, k / gx);
            ((i, j), (i, j + 1))
        };
        let (a, b) = if inside(a.0, a.1) { (a, b) } else { (b, a) };
        let t = grid.crossing(a, b);
        let pa = grid.position(a.0, a.1);
        let pb = grid.position(b.0, b.1);
        (pa.0 + t * (pb.0 - pa.0), pa.1 + t * (pb.1 - pa.1))
    };

    let mut visited = vec![false; adj.len()];
    let mut lines = Vec::new();
    for start in 0..adj.len() {
        if visited[start] || adj[start][0] == NONE {
            continue;
        }
        let mut line = vec![point(start)];
        visited[start] = true;
        let mut current = start;
        loop {
            let next = adj[current]
                .iter()
                .copied()
                .find(|&n| n != NONE && !visited[n]);
            match next {
                Some(n) => {
                    visited[n] = true;
                    line.push(point(n));
                    current = n;
                }
                None => break,
            }
        }
        // Close the curve if its last edge links back to the start (always, for a valid grid).
        if adj[current].contains(&start) {
            line.push(line[0]);
        }
        lines.push(line);
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn single_cell_gives_a_closed_diamond() {
        let v = [0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0];
        let lines = contour_zero(3, 3, 0.0, 0.0, 1.0, 1.0, &v);
        assert_eq!(lines.len(), 1);
        assert_eq!(lines[0].len(), 5);
        assert_eq!(lines[0].first(), lines[0].last());
        for &(x, y) in &lines[0] {
            assert!(((x - 1.5).abs() + (y - 1.5).abs() - 0.5).abs() < 1e-12);
        }
    }

    #[test]
    fn full_field_is_bounded_by_the_grid_edge() {
        let v = [1.0; 6];
        let lines = contour_zero(3, 2, -1.0, 2.0, 0.5, 1.0, &v);
        assert_eq!(lines.len(), 1);
        for &(x, y) in &lines[0] {
            assert!((-1.0..=0.5).contains(&x) && (2.0..=4.0).contains(&y));
        }
        assert!(lines[0].iter().any(|&(x, y)| x == -1.0 && y == 2.5));
    }

    #[test]
    fn bad_input_gives_nothing() {
        assert!(contour_zero(2, 2, 0.0, 0.0, 1.0, 1.0, &[1.0; 3]).is_empty());
        assert!(contour_zero(0, 2, 0.0, 0.0, 1.0, 1.0, &[]).is_empty());
        assert!(contour_zero(2, 2, 0.0, 0.0, 1.0, 1.0, &[0.0; 4]).is_empty());
    }
}
