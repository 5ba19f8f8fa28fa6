//! The trackgen model compiler.
//!
//! [`model!`] reads a declarative description of a planar tracked vehicle
//! (or of a free track) and generates specialised, unrolled code for its
//! dynamics in recursive coordinates: positions (eq. (4)), the velocity
//! transform as the structured product `H̄₁ H̄ₙ` (eq. (7)), the quadratic
//! velocity terms `γ` (eq. (14)), the mass matrix `M_i` from the closed
//! forms of formulation §1, `Q_i` in O(n), the loop closure (formulation §2) and the
//! chassis tree (formulation §3). Every constant is folded at compile time.
//!
//! The pipeline follows serde_derive: `parse` turns tokens into a syntax
//! tree that keeps every span, `lower` validates it into an IR and
//! collects *all* errors, and `codegen` writes the code. The whole
//! expansion is the plain function `expand::expand`, tested on
//! `proc_macro2` token streams.
//!
//! Users reach this macro as `trackgen::model!`; its documentation, with
//! the full syntax, lives there.

mod codegen;
mod expand;
mod ir;
mod lower;
mod num;
mod parse;

#[cfg(test)]
mod properties;
#[cfg(test)]
mod tests;

/// Declares tracks and vehicles and compiles their dynamics. See the
/// `trackgen` crate for the syntax.
#[proc_macro]
pub fn model(input: proc_macro::TokenStream) -> proc_macro::TokenStream {
    expand::expand(input.into()).into()
}
