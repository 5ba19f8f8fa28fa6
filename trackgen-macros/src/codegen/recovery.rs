//! The closure under generalised coordinate partitioning (formulation §2, the
//! paper's eqs. (17)-(21)), generated: `TrackModel::recover_closure` and
//! `TrackModel::closure_columns`.
//!
//! With `C = Σ Aʲ d̄ʲ` and the dependent pair `k, l`, everything but the
//! pair is fixed while Newton-Raphson moves it: the sum over every link is
//! taken once (one loop, each span `d̄ʲ` folded; every link's sine and
//! cosine by the runtime's vectorised `sin_cos_each`), the pair's share
//! taken out, and the Newton step `C_d⁻¹ C` on the 2 × 2 block
//! `C_d = [A_θᵏ d̄ᵏ, A_θˡ d̄ˡ]` uses the pair's spans only. The pair's rates
//! follow from `C_q q̇ = 0`: `ḋ = −C_d⁻¹ C_z ż`.

use proc_macro2::TokenStream;
use quote::quote;

use super::per_link::{PerLink, expr};
use super::runtime_path::runtime;
use crate::ir::{Closure, Track};

/// Every link's span `d̄ʲ = ū2ʲ − ū1ʲ`, folded.
fn spans(track: &Track) -> [PerLink; 2] {
    let span = |f: fn(&crate::ir::Link) -> crate::num::Num| track.links.iter().map(f).collect();
    [
        PerLink::new("SPAN_X", span(|l| l.u2.x.clone() - l.u1.x.clone())),
        PerLink::new("SPAN_Y", span(|l| l.u2.y.clone() - l.u1.y.clone())),
    ]
}

/// `A d̄` at link `j` from its `(s, c)`: (c dₓ − s d_y, s dₓ + c d_y).
fn turned(spans: &[PerLink; 2], j: TokenStream) -> (TokenStream, TokenStream) {
    let (dx, dy) = (spans[0].at(j.clone()), spans[1].at(j));
    let x = dx
        .clone()
        .times(&quote!(c))
        .minus(dy.clone().times(&quote!(s)));
    let y = dx.times(&quote!(s)).plus(dy.times(&quote!(c)));
    (expr(x), expr(y))
}

/// The statements of a track's `tree_dynamics`: its linear-time route with
/// the closing joint cut, and a declared penalty spring's force across the
/// cut (its gap `C = Σ Aʲ d̄ʲ` and rate from `trig` and `qd`).
pub fn cut_dynamics(track: &Track) -> TokenStream {
    let rt = runtime();
    let n = track.links.len();
    let v2 = quote!(#rt::nalgebra::Vector2::<f64>);
    let closing = match &track.closure {
        Closure::Penalty { stiffness, damping } => {
            let spans = spans(track);
            let tables: TokenStream = spans.iter().map(PerLink::declaration).collect();
            let (ax, ay) = turned(&spans, quote!(j));
            quote! {{
                #tables
                let (mut gap, mut rate) = (<#v2>::zeros(), <#v2>::zeros());
                for j in 0..#n {
                    let (s, c) = trig[j];
                    let (ax, ay) = (#ax, #ay);
                    gap += <#v2>::new(ax, ay);
                    rate += <#v2>::new(-ay, ax) * qd[2 + j];
                }
                let joint = #rt::PenaltyJoint { stiffness: #stiffness, damping: #damping };
                #rt::ClosingJoint::Cut { force: joint.force(gap, rate) }
            }}
        }
        _ => quote!(#rt::ClosingJoint::OPEN),
    };
    quote! {
        ::core::assert_eq!(trig.len(), #n, "one (sin θ, cos θ) per link");
        let closing = #closing;
        let mut forces = [<#v2>::zeros(); #n];
        #rt::TrackModel::linear_time_dynamics(self, trig, qd, loads, closing, qdd, &mut forces)
    }
}

/// `recover_closure` and `closure_columns` of a track.
pub fn recovery(track: &Track) -> TokenStream {
    let rt = runtime();
    let n = track.links.len();
    let dof = n + 2;
    let spans = spans(track);
    let tables: TokenStream = spans.iter().map(PerLink::declaration).collect();
    let (ax, ay) = turned(&spans, quote!(j));
    let (span_x, span_y) = (expr(spans[0].at(quote!(j))), expr(spans[1].at(quote!(j))));
    let v2 = quote!(#rt::nalgebra::Vector2::<f64>);
    quote! {
        fn recover_closure(
            &self,
            q: &mut #rt::nalgebra::SVector<f64, #dof>,
            qd: &mut #rt::nalgebra::SVector<f64, #dof>,
            pair: [usize; 2],
            tolerance: f64,
            max_iterations: usize,
            trig: &mut [(f64, f64)],
        ) -> ::core::result::Result<usize, (usize, f64)> {
            const N: usize = #n;
            #tables
            #[inline(always)]
            fn span(j: usize) -> (f64, f64) {
                (#span_x, #span_y)
            }
            #[inline(always)]
            fn turn((s, c): (f64, f64), (x, y): (f64, f64)) -> (f64, f64) {
                (c * x - s * y, s * x + c * y)
            }
            let trig: &mut [(f64, f64); N] = trig.try_into().expect("one (sin θ, cos θ) per link");
            let [k, l] = pair;
            ::core::assert!(k != l && k < N && l < N, "the dependent pair: two different links");
            #rt::sin_cos_each(&q.as_slice()[2..], trig);
            // C and C_q q̇ over every link, then without the pair's share.
            let (mut cx, mut cy, mut vx, mut vy) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
            for j in 0..N {
                let (s, c) = trig[j];
                let (ax, ay) = (#ax, #ay);
                let w = qd[2 + j];
                cx += ax;
                cy += ay;
                vx -= ay * w;
                vy += ax * w;
            }
            let (dk, dl) = (span(k), span(l));
            let (ak, al) = (turn(trig[k], dk), turn(trig[l], dl));
            let (wk, wl) = (qd[2 + k], qd[2 + l]);
            let rest = (cx - ak.0 - al.0, cy - ak.1 - al.1);
            let rate = (vx + ak.1 * wk + al.1 * wl, vy - ak.0 * wk - al.0 * wl);
            // Newton-Raphson on the pair. C_d's columns are A_θ d̄ = (−a_y, aₓ),
            // det C_d = aₖₓ a_l_y − aₖ_y a_lₓ, C_d⁻¹ = [[a_lₓ, a_l_y], [−aₖₓ, −aₖ_y]] / det.
            // One step more once within the tolerance: converging
            // quadratically, it takes the closure to rounding, so the
            // result does not jump with the iterations taken (a state's
            // accelerations smooth in the state, to the last digits).
            let mut iteration = 0usize;
            let mut within = false;
            let (ak, al) = loop {
                let (tk, tl) = (#rt::sin_cos(q[2 + k]), #rt::sin_cos(q[2 + l]));
                let (ak, al) = (turn(tk, dk), turn(tl, dl));
                let (gx, gy) = (rest.0 + ak.0 + al.0, rest.1 + ak.1 + al.1);
                let residual = (gx * gx + gy * gy).sqrt();
                if residual <= tolerance && within {
                    trig[k] = tk;
                    trig[l] = tl;
                    break (ak, al);
                }
                within = residual <= tolerance;
                let det = ak.0 * al.1 - ak.1 * al.0;
                if (iteration >= max_iterations && !within) || !residual.is_finite() || det == 0.0 {
                    return ::core::result::Result::Err((iteration, residual));
                }
                q[2 + k] -= (al.0 * gx + al.1 * gy) / det;
                q[2 + l] += (ak.0 * gx + ak.1 * gy) / det;
                iteration += 1;
            };
            let det = ak.0 * al.1 - ak.1 * al.0;
            if !(det != 0.0 && det.is_finite()) {
                return ::core::result::Result::Err((iteration, 0.0));
            }
            qd[2 + k] = -(al.0 * rate.0 + al.1 * rate.1) / det;
            qd[2 + l] = (ak.0 * rate.0 + ak.1 * rate.1) / det;
            ::core::result::Result::Ok(iteration)
        }

        fn closure_columns(&self, trig: &[(f64, f64)], out: &mut [#v2]) {
            const N: usize = #n;
            #tables
            ::core::assert!(trig.len() == N && out.len() == N, "one entry per link");
            for j in 0..N {
                let (s, c) = trig[j];
                let (ax, ay) = (#ax, #ay);
                out[j] = <#v2>::new(-ay, ax);
            }
        }
    }
}
