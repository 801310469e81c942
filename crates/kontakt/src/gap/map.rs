//! User-supplied gap or height maps on a uniform grid (in memory; the case layer,
//! `kontakt-case`, reads them from CSV or NumPy `.npy` files).

use crate::error::{Error, Result, positive_as};
use crate::geometry::Grid2;

/// What the map's values are.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize, schemars::JsonSchema)
)]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum MapKind {
    /// The undeformed gap between the bodies \[mm\], used as it is (the approach is
    /// measured from its zero level).
    #[default]
    Gap,
    /// The height \[mm\] of the combined (sum) topography of the two surfaces, pressed
    /// against each other: the gap is `max(z) - z`, so the highest summit touches first.
    Height,
}

/// A gap on a uniform cell-centred grid centred on the origin \[mm\].
#[derive(Debug, Clone, PartialEq)]
pub struct GapMap {
    grid: Grid2,
    values: Vec<f64>,
}

impl GapMap {
    /// A map from `values` (row-major, x fastest: `ny` rows of `nx` values) with cell
    /// spacing `spacing = [dx, dy]` \[mm\].
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a count that is not `nx·ny`, a non-finite value (the
    /// error names its row and column), a non-positive spacing, or fewer than 2 cells a
    /// side.
    pub fn new(
        nx: usize,
        ny: usize,
        spacing: [f64; 2],
        values: Vec<f64>,
        kind: MapKind,
    ) -> Result<Self> {
        positive_as("spacing[0]", spacing[0], "a finite cell size > 0 mm")?;
        positive_as("spacing[1]", spacing[1], "a finite cell size > 0 mm")?;
        if nx < 2 || ny < 2 {
            return Err(Error::invalid(
                "gap_map",
                format!("{nx} x {ny} cells"),
                "at least 2 x 2 cells",
            ));
        }
        if values.len() != nx * ny {
            return Err(Error::invalid(
                "gap_map",
                format!("{} values", values.len()),
                format!("{} values for {nx} x {ny} cells", nx * ny),
            ));
        }
        if let Some(k) = values.iter().position(|v| !v.is_finite()) {
            return Err(Error::invalid(
                "gap_map",
                format!("{} at row {}, column {}", values[k], k / nx + 1, k % nx + 1),
                "finite values in mm",
            ));
        }
        // A huge cell size over many cells overflows the map's extent (found by fuzzing:
        // the error named the grid's `y_range`, not the key the user wrote).
        for (i, n) in [nx, ny].into_iter().enumerate() {
            if !(n as f64 * spacing[i]).is_finite() {
                return Err(Error::invalid(
                    if i == 0 { "spacing[0]" } else { "spacing[1]" },
                    spacing[i],
                    format!("a cell size whose {n} cells span a finite extent in mm"),
                ));
            }
        }
        let grid = Grid2::centered(
            0.5 * nx as f64 * spacing[0],
            0.5 * ny as f64 * spacing[1],
            nx,
            ny,
        )?;
        let values = match kind {
            MapKind::Gap => values,
            MapKind::Height => {
                let top = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
                values.into_iter().map(|z| top - z).collect()
            }
        };
        Ok(GapMap { grid, values })
    }

    /// The grid \[mm\].
    pub fn grid(&self) -> &Grid2 {
        &self.grid
    }

    /// The gap per cell \[mm\], row-major with x fastest.
    pub fn values(&self) -> &[f64] {
        &self.values
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nan_and_shape_errors_name_the_place() {
        let e = GapMap::new(
            2,
            2,
            [0.1, 0.1],
            vec![0.0, 1.0, f64::NAN, 2.0],
            MapKind::Gap,
        )
        .unwrap_err();
        assert_eq!(e.field(), Some("gap_map"));
        assert!(e.to_string().contains("row 2, column 1"), "{e}");
        let e = GapMap::new(2, 2, [0.1, 0.1], vec![0.0; 3], MapKind::Gap).unwrap_err();
        assert!(e.to_string().contains("4 values"), "{e}");
        let e = GapMap::new(2, 2, [0.0, 0.1], vec![0.0; 4], MapKind::Gap).unwrap_err();
        assert_eq!(e.field(), Some("spacing[0]"));
    }

    #[test]
    fn height_map_turns_into_a_gap() {
        let m = GapMap::new(2, 2, [0.1, 0.1], vec![0.0, 3.0, 1.0, 2.0], MapKind::Height).unwrap();
        assert_eq!(m.values(), &[3.0, 0.0, 2.0, 1.0]);
    }
}
