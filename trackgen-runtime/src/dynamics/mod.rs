//! Forward dynamics at a given state: `q̈_i` from `(q_i, q̇_i)`.
//!
//! Both routes end in the same dense solves (formulation §2): an open (or
//! penalty-closed) chain solves `M_i q̈_i = Q_i` by Cholesky; a loop closed by
//! a constraint solves the multiplier form
//!
//! ```text
//! [ M_i  C_qᵀ ] [ q̈_i ]   [ Q_i ]
//! [ C_q   0   ] [  λ  ] = [ γ_c ]
//! ```
//!
//! by the range-space method: with `y = M_i⁻¹ Q_i` and `X = M_i⁻¹ C_qᵀ`,
//! `(C_q X) λ = C_q y − γ_c` and `q̈_i = y − X λ`. Both are O(n³) in the
//! number of links; they are the dense cross-check.
//!
//! `M_i` is `8 · DOF²` bytes: up to [`STACK_MATRIX_BYTES`] (64 KiB, DOF 90)
//! it is built and factorised on the stack; beyond, on the heap (8 MB at
//! 1000 links), so every route runs on a 2 MiB thread for any track the
//! macro accepts.

mod declared;
mod dense;
pub mod derivative;
pub(crate) mod elimination;
mod generated;
#[cfg(feature = "oracle")]
mod linear_time;
mod shifted;

pub use declared::track_dynamics;
pub use dense::Accelerations;
#[cfg(feature = "oracle")]
pub(crate) use dense::{solve_closed, solve_open};
pub use derivative::{StateJacobian, track_jacobian, tree_jacobian};
pub use generated::{STACK_MATRIX_BYTES, dense_forward_dynamics, dense_open_dynamics};
#[cfg(feature = "oracle")]
pub use linear_time::LinearTimeSolver;
pub use shifted::ShiftedChain;
