//! A cache of [`HalfSpacePlan`]s keyed by grid, like RustFFT's `FftPlanner` caches FFT
//! plans by length.

use super::operator::{Boundary, HalfSpacePlan, resolve_threads};
use crate::error::{Result, positive_as};
use crate::geometry::Grid2;
use std::sync::Arc;

/// What a plan depends on: cells, spacing (bit pattern, \[mm\]), boundary, contact
/// modulus (bit pattern, \[MPa\]) and the resolved thread count. The grid's origin does
/// not enter the operator.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
struct Key {
    cells: [usize; 2],
    spacing: [u64; 2],
    boundary: Boundary,
    e_star: u64,
    threads: usize,
}

/// Plans the elastic operator once per grid and hands out the shared plan: equal keys
/// (cells, spacing \[mm\], boundary, contact modulus E* \[MPa\], threads) return the same
/// [`Arc<HalfSpacePlan>`].
///
/// E* is part of the key and every plan's kernel is built for its own E*, exactly as an
/// unshared plan, so that results stay bit-identical. (The kernel is proportional to
/// 1/E*: keying on the grid alone and scaling a unit-E* kernel per material pair is
/// possible later, at the price of the last bits.)
///
/// A planner is a plain cache (`&mut self`, like `FftPlanner`); share one between
/// threads behind a `Mutex`, as [`super::Bem`] does. It keeps at most
/// [`HalfSpacePlanner::capacity`] plans and at most
/// [`HalfSpacePlanner::DEFAULT_MEMORY_BUDGET`] bytes of kernels (always the newest plan),
/// and forgets the least recently used plans beyond that, so that a long run over many
/// domains does not hold every kernel it ever planned.
#[derive(Debug)]
pub struct HalfSpacePlanner {
    /// Most recently used last.
    plans: Vec<(Key, Arc<HalfSpacePlan>)>,
    capacity: usize,
    built: usize,
}

impl Default for HalfSpacePlanner {
    fn default() -> Self {
        Self::new()
    }
}

impl HalfSpacePlanner {
    /// Plans kept by [`HalfSpacePlanner::new`].
    pub const DEFAULT_CAPACITY: usize = 16;

    /// Bytes of kernel spectra kept (512 MiB): beyond it the least recently used plans
    /// are forgotten, the newest is always kept.
    pub const DEFAULT_MEMORY_BUDGET: usize = 512 << 20;

    /// An empty planner keeping up to [`HalfSpacePlanner::DEFAULT_CAPACITY`] plans.
    pub fn new() -> Self {
        Self::with_capacity(Self::DEFAULT_CAPACITY)
    }

    /// An empty planner keeping up to `capacity` plans (at least one).
    pub fn with_capacity(capacity: usize) -> Self {
        HalfSpacePlanner {
            plans: Vec::new(),
            capacity: capacity.max(1),
            built: 0,
        }
    }

    /// The plan of the operator on `grid` \[mm\] for the contact modulus `e_star` \[MPa\],
    /// `boundary` and `threads` (as [`HalfSpacePlan::new`]): the cached one when a plan of
    /// equal cells, spacing, boundary, E* and threads exists, a new one otherwise. The
    /// returned plan [`serves`](HalfSpacePlan::serves) `grid`; its own
    /// [`grid`](HalfSpacePlan::grid) is the first grid it was planned for.
    ///
    /// # Errors
    /// [`crate::Error::InvalidInput`] for a non-positive modulus or `threads` outside 1..=[`crate::MAX_THREADS`].
    pub fn plan(
        &mut self,
        grid: &Grid2,
        e_star: f64,
        boundary: Boundary,
        threads: Option<usize>,
    ) -> Result<Arc<HalfSpacePlan>> {
        positive_as("e_star", e_star, "a finite contact modulus > 0 MPa")?;
        let key = Key {
            cells: [grid.nx(), grid.ny()],
            spacing: [grid.dx().to_bits(), grid.dy().to_bits()],
            boundary,
            e_star: e_star.to_bits(),
            threads: resolve_threads(threads)?,
        };
        if let Some(at) = self.plans.iter().position(|(k, _)| *k == key) {
            let entry = self.plans.remove(at);
            let plan = Arc::clone(&entry.1);
            self.plans.push(entry);
            return Ok(plan);
        }
        let plan = Arc::new(HalfSpacePlan::build(grid, e_star, boundary, key.threads)?);
        self.built += 1;
        self.plans.push((key, Arc::clone(&plan)));
        while self.plans.len() > 1
            && (self.plans.len() > self.capacity
                || self.memory_bytes() > Self::DEFAULT_MEMORY_BUDGET)
        {
            self.plans.remove(0);
        }
        Ok(plan)
    }

    /// Plans held.
    pub fn len(&self) -> usize {
        self.plans.len()
    }

    /// Whether no plan is held.
    pub fn is_empty(&self) -> bool {
        self.plans.is_empty()
    }

    /// Most plans held.
    pub fn capacity(&self) -> usize {
        self.capacity
    }

    /// Plans built since the planner was made (cache misses).
    pub fn plans_built(&self) -> usize {
        self.built
    }

    /// Bytes held by the cached plans (see [`HalfSpacePlan::memory_bytes`]).
    pub fn memory_bytes(&self) -> usize {
        self.plans.iter().map(|(_, p)| p.memory_bytes()).sum()
    }

    /// Forget every plan (plans still in use elsewhere live on).
    pub fn clear(&mut self) {
        self.plans.clear();
    }
}
