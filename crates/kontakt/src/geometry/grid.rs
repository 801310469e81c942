//! Uniform rectangular sampling grids in the contact plane.

use crate::error::{Error, Result};
use crate::units::Millimetre;

/// A uniform, cell-centred grid of `nx × ny` points in the contact plane \[mm\].
///
/// Point `(i, j)` sits at `x = x_min + (i + 1/2) dx`, `y = y_min + (j + 1/2) dy`, the
/// centre of cell `(i, j)`. Fields sampled on the grid are stored row-major with `x`
/// fastest: index `j * nx + i`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Grid2 {
    nx: usize,
    ny: usize,
    x_min: Millimetre,
    y_min: Millimetre,
    dx: Millimetre,
    dy: Millimetre,
}

impl Grid2 {
    /// A grid covering `[x_min, x_max] × [y_min, y_max]` \[mm\] with `nx × ny` cells.
    ///
    /// # Errors
    /// `nx`/`ny` must be in 1..=65536 and each range finite with `min < max`.
    pub fn new(
        x_range: [Millimetre; 2],
        y_range: [Millimetre; 2],
        nx: usize,
        ny: usize,
    ) -> Result<Self> {
        for (field, n) in [("nx", nx), ("ny", ny)] {
            if !(1..=65_536).contains(&n) {
                return Err(Error::invalid(field, n, "1 <= n <= 65536 cells"));
            }
        }
        for (field, r) in [("x_range", x_range), ("y_range", y_range)] {
            if !(r[0].is_finite() && r[1].is_finite() && r[0] < r[1]) {
                return Err(Error::invalid(
                    field,
                    format!("[{}, {}]", r[0], r[1]),
                    "finite bounds in mm with min < max",
                ));
            }
        }
        Ok(Grid2 {
            nx,
            ny,
            x_min: x_range[0],
            y_min: y_range[0],
            dx: (x_range[1] - x_range[0]) / nx as f64,
            dy: (y_range[1] - y_range[0]) / ny as f64,
        })
    }

    /// A grid centred on the origin with half-extents `half_x`, `half_y` \[mm\].
    ///
    /// # Errors
    /// As [`Grid2::new`]; half-extents must be finite and > 0.
    pub fn centered(half_x: Millimetre, half_y: Millimetre, nx: usize, ny: usize) -> Result<Self> {
        Self::new([-half_x, half_x], [-half_y, half_y], nx, ny)
    }

    /// Number of points along x.
    pub fn nx(&self) -> usize {
        self.nx
    }
    /// Number of points along y.
    pub fn ny(&self) -> usize {
        self.ny
    }
    /// Total number of points.
    pub fn len(&self) -> usize {
        self.nx * self.ny
    }
    /// Always false: a grid has at least one point.
    pub fn is_empty(&self) -> bool {
        false
    }
    /// Cell size along x \[mm\].
    pub fn dx(&self) -> Millimetre {
        self.dx
    }
    /// Cell size along y \[mm\].
    pub fn dy(&self) -> Millimetre {
        self.dy
    }
    /// Cell area \[mm²\].
    pub fn cell_area(&self) -> f64 {
        self.dx * self.dy
    }
    /// x coordinate of column `i` \[mm\].
    pub fn x(&self, i: usize) -> Millimetre {
        self.x_min + (i as f64 + 0.5) * self.dx
    }
    /// y coordinate of row `j` \[mm\].
    pub fn y(&self, j: usize) -> Millimetre {
        self.y_min + (j as f64 + 0.5) * self.dy
    }
    /// All points `(x, y)` in storage order (row-major, x fastest).
    pub fn points(&self) -> impl Iterator<Item = (Millimetre, Millimetre)> + '_ {
        (0..self.ny).flat_map(move |j| (0..self.nx).map(move |i| (self.x(i), self.y(j))))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layout_and_validation() {
        let g = Grid2::centered(1.0, 0.5, 4, 2).unwrap();
        assert_eq!(g.len(), 8);
        assert_eq!(g.x(0), -0.75);
        assert_eq!(g.y(1), 0.25);
        let pts: Vec<_> = g.points().collect();
        assert_eq!(pts[1], (-0.25, -0.25));
        assert_eq!(pts[4], (-0.75, 0.25));
        assert!((g.cell_area() - 0.25).abs() < 1e-15);
        assert!(Grid2::centered(1.0, 1.0, 0, 3).is_err());
        assert!(Grid2::centered(-1.0, 1.0, 3, 3).is_err());
        assert!(Grid2::new([0.0, f64::NAN], [0.0, 1.0], 3, 3).is_err());
    }
}
