//! The reference (textbook) route: the dynamics of a [`TreeDescription`](crate::multibody::TreeDescription)
//! evaluated at run time exactly as the paper writes them.
//!
//! The dense velocity transform `H` is assembled column by column from
//! eq. (6) (eq. (11) for a chassis), `γ` from eq. (14), and then
//! `M_i = Hᵀ M H` and `Q_i = Hᵀ (Q − M γ)` (eqs. (15), (16)) by dense
//! products, O(n³). Nothing here shares code with the generator: it is the
//! oracle that generated code is tested against, and the baseline the
//! benchmarks compare with.

mod model;

pub use model::ReferenceModel;
