//! `TrackModel::linear_time_dynamics`: the track's forward dynamics in
//! O(n) by formulation §5, generated.
//!
//! Unknowns are each link's absolute accelerations and each joint's force
//! `λ`; with `D⁺ⱼ = [A_θʲ ū2ʲ | I]`, `D⁻ₖ = [A_θᵏ ū1ᵏ | I]` and
//! `Wᵢ = diag(1/Jᵢ, 1/mᵢ, 1/mᵢ)` the joint forces solve a symmetric
//! block-tridiagonal system of 2 × 2 blocks (cyclic for a constrained
//! loop):
//!
//! ```text
//! diagonal  D⁺ⱼ Wⱼ D⁺ⱼᵀ + D⁻ₖ Wₖ D⁻ₖᵀ = pⱼ pⱼᵀ/Jⱼ + pₖ pₖᵀ/Jₖ + (1/mⱼ + 1/mₖ) I
//! coupling  Lⱼ = −D⁺ⱼ Wⱼ D⁻ⱼᵀ = −(p2ʲ p1ʲᵀ/Jⱼ + I/mⱼ)            (joint j to joint j − 1)
//! right     κⱼ − D⁺ⱼ Wⱼ Fⱼ + D⁻ₖ Wₖ Fₖ
//! ```
//!
//! with `p1ⁱ = A_θⁱ ū1ⁱ`, `p2ⁱ = A_θⁱ ū2ⁱ`. The generated code builds each
//! joint's blocks as it eliminates them (one forward pass storing the
//! factors `Fⱼ = Lⱼ Dⱼ₋₁⁻¹` and the reduced right sides
//! `yⱼ = Dⱼ⁻¹ r̂ⱼ`), substitutes back (`xⱼ = yⱼ − Fⱼ₊₁ᵀ xⱼ₊₁`), and for a
//! constrained loop carries the closing joint's two columns along and
//! closes with a 2 × 2 Schur complement (bordering). The accelerations
//! follow link by link, `aᵢ = Wᵢ (Fᵢ + D⁺ᵢᵀ λᵢ − D⁻ᵢᵀ λᵢ₋₁)`.
//!
//! Every per-link constant (`1/m`, `1/J`, `m g`, `ū1`, `ū2`) is folded:
//! one shared by every link is a number in the code (and a zero drops its
//! terms); one that differs between links is a table the loop reads. The
//! code is a loop over the links, so it does not grow with their number
//! (unrolling would fold nothing more), and the const-generic `solve`
//! specialises it for the constrained and the cut loop.

use proc_macro2::TokenStream;
use quote::quote;

use super::lin::Lin;
use super::per_link::{PerLink, expr};
use super::runtime_path::runtime;
use crate::ir::Track;
use crate::num::Num;

/// The per-link constants of the solve.
struct Fields {
    inv_mass: PerLink,
    inv_inertia: PerLink,
    weight: [PerLink; 2],
    u1: [PerLink; 2],
    u2: [PerLink; 2],
}

impl Fields {
    fn new(track: &Track) -> Fields {
        let field = |name: &str, f: &dyn Fn(&crate::ir::Link) -> Num| {
            PerLink::new(name, track.links.iter().map(f).collect())
        };
        let one = || Num::Known(1.0);
        let (gx, gy) = (&track.gravity.x, &track.gravity.y);
        Fields {
            inv_mass: field("INV_MASS", &|l| one() / l.mass.clone()),
            inv_inertia: field("INV_INERTIA", &|l| one() / l.inertia.clone()),
            weight: [
                field("WEIGHT_X", &|l| l.mass.clone() * gx.clone()),
                field("WEIGHT_Y", &|l| l.mass.clone() * gy.clone()),
            ],
            u1: [
                field("U1_X", &|l| l.u1.x.clone()),
                field("U1_Y", &|l| l.u1.y.clone()),
            ],
            u2: [
                field("U2_X", &|l| l.u2.x.clone()),
                field("U2_Y", &|l| l.u2.y.clone()),
            ],
        }
    }

    fn declarations(&self) -> TokenStream {
        [
            &self.inv_mass,
            &self.inv_inertia,
            &self.weight[0],
            &self.weight[1],
            &self.u1[0],
            &self.u1[1],
            &self.u2[0],
            &self.u2[1],
        ]
        .into_iter()
        .map(PerLink::declaration)
        .collect()
    }

    /// `A_θ u = (−(s uₓ + c u_y), c uₓ − s u_y)` at link `i`.
    fn lever(u: &[PerLink; 2], i: &TokenStream) -> (TokenStream, TokenStream) {
        let (ux, uy) = (u[0].at(i.clone()), u[1].at(i.clone()));
        let x = ux
            .clone()
            .times(&quote!(s))
            .plus(uy.clone().times(&quote!(c)))
            .scaled(&Num::Known(-1.0));
        let y = ux.times(&quote!(c)).minus(uy.times(&quote!(s)));
        (expr(x), expr(y))
    }

    /// Everything of link `i` that the joint blocks need, bound as locals
    /// (`s`, `c`, `w` its angle's sine, cosine and rate, `load_x`,
    /// `load_y`, `moment` its load): the levers `p1`, `p2`, the blocks
    /// `A2 = p2 p2ᵀ/J + I/m` and `A1 = p1 p1ᵀ/J + I/m` (symmetric), the
    /// coupling `L = −(p2 p1ᵀ/J + I/m)`, and the right-side terms
    /// `e2 = A ū2 ω² − p2 T/J − F/m`, `e1 = A ū1 ω² − p1 T/J − F/m`.
    fn link_terms(&self, i: &TokenStream) -> TokenStream {
        let (p1x, p1y) = Fields::lever(&self.u1, i);
        let (p2x, p2y) = Fields::lever(&self.u2, i);
        let ij = self.inv_inertia.at(i.clone());
        let im = self.inv_mass.at(i.clone());
        let over_j = |v: TokenStream| expr(ij.clone().times(&v));
        let plus_m = |v: TokenStream| expr(ij.clone().times(&v).plus(im.clone()));
        let (a2xx, a2xy, a2yy) = (
            plus_m(quote!((p2x * p2x))),
            over_j(quote!((p2x * p2y))),
            plus_m(quote!((p2y * p2y))),
        );
        let (a1xx, a1xy, a1yy) = (
            plus_m(quote!((p1x * p1x))),
            over_j(quote!((p1x * p1y))),
            plus_m(quote!((p1y * p1y))),
        );
        let (l00, l01, l10, l11) = (
            plus_m(quote!((p2x * p1x))),
            over_j(quote!((p2x * p1y))),
            over_j(quote!((p2y * p1x))),
            plus_m(quote!((p2y * p1y))),
        );
        let fx = expr(self.weight[0].at(i.clone()).plus(Lin::var(quote!(load_x))));
        let fy = expr(self.weight[1].at(i.clone()).plus(Lin::var(quote!(load_y))));
        let torque = over_j(quote!(moment));
        let (fmx, fmy) = (
            expr(im.clone().times(&quote!(fx))),
            expr(im.times(&quote!(fy))),
        );
        quote! {
            let p1x = #p1x;
            let p1y = #p1y;
            let p2x = #p2x;
            let p2y = #p2y;
            let fx = #fx;
            let fy = #fy;
            // T/J and F/m.
            let tj = #torque;
            let (fmx, fmy) = (#fmx, #fmy);
            let ww = w * w;
            let link_a2 = [#a2xx, #a2xy, #a2yy];
            let link_a1 = [#a1xx, #a1xy, #a1yy];
            let link_l = [-#l00, -#l01, -#l10, -#l11];
            // A u = (p_y, −pₓ).
            let link_e2 = [p2y * ww - p2x * tj - fmx, -p2x * ww - p2y * tj - fmy];
            let link_e1 = [p1y * ww - p1x * tj - fmx, -p1x * ww - p1y * tj - fmy];
        }
    }
}

/// The `linear_time_dynamics` method of a track.
pub fn linear_time_dynamics(track: &Track) -> TokenStream {
    let rt = runtime();
    let n = track.links.len();
    let dof = n + 2;
    let m = n - 1;
    let fields = Fields::new(track);
    let tables = fields.declarations();
    let link_terms = fields.link_terms(&quote!(i));
    let ij_i = expr(fields.inv_inertia.at(quote!(i)));
    let im_first = expr(fields.inv_mass.at(quote!(0usize)));
    let (ij_first, ij_last) = (
        expr(fields.inv_inertia.at(quote!(0usize))),
        expr(fields.inv_inertia.at(quote!(#m))),
    );
    let (im_first_cut, im_last) = (
        expr(fields.inv_mass.at(quote!(0usize))),
        expr(fields.inv_mass.at(quote!(#m))),
    );
    let singular = quote!(#rt::DynamicsError::SingularJointSystem);
    let v2 = quote!(#rt::nalgebra::Vector2::<f64>);
    let elimination = quote!(#rt::elimination);
    // Joint j's row: its blocks from its two links' terms, and for a
    // constrained loop the closing joint's columns (b₀ = L₁ at joint 0,
    // b_m = L_nᵀ at joint n − 1).
    let row_j = quote! {
        let k = j + 1;
        let mut d = [links[j].a2[0] + links[k].a1[0], links[j].a2[1] + links[k].a1[1], links[j].a2[2] + links[k].a1[2]];
        let mut r = [links[j].e2[0] - links[k].e1[0], links[j].e2[1] - links[k].e1[1]];
        let mut z = [0.0f64; 4];
        if CLOSED {
            if j == 0 {
                z = links[0].coupling;
            }
            if j + 1 == M {
                let b = links[N - 1].coupling;
                z = [z[0] + b[0], z[1] + b[2], z[2] + b[1], z[3] + b[3]];
            }
        }
    };
    let link_pass = link_pass(
        &link_terms,
        &elimination,
        [&ij_first, &im_first_cut, &ij_last, &im_last],
    );
    let elimination_sweeps = elimination_sweeps(&row_j);
    let forces_and_accelerations = forces_and_accelerations(&singular, &v2, &ij_i, &im_first);
    // A loop of fewer than 3 links cannot close.
    let constrained = if n >= 3 {
        quote! {
            #rt::ClosingJoint::Constrained { stabilisation } => {
                solve::<true>(trig, qd, loads, stabilisation, <#v2>::zeros(), qdd, joint_forces, links, joints)
            }
        }
    } else {
        quote! {
            #rt::ClosingJoint::Constrained { .. } => {
                ::core::result::Result::Err(#rt::DynamicsError::WrongLength {
                    what: "links of a closed loop (at least 3)",
                    expected: 3,
                    got: #n,
                })
            }
        }
    };
    quote! {
        fn linear_time_dynamics(
            &self,
            trig: &[(f64, f64)],
            qd: &#rt::nalgebra::SVector<f64, #dof>,
            loads: &[#rt::BodyLoad],
            closing: #rt::ClosingJoint,
            qdd: &mut #rt::nalgebra::SVector<f64, #dof>,
            joint_forces: &mut [#v2],
        ) -> ::core::result::Result<(), #rt::DynamicsError> {
            // Spec §5, specialised for a constrained (`CLOSED`) or a cut
            // loop; see `trackgen-macros/src/codegen/linear_time.rs`.
            #[inline(always)]
            fn solve<const CLOSED: bool>(
                trig: &[(f64, f64); #n],
                qd: &#rt::nalgebra::SVector<f64, #dof>,
                loads: &[#rt::BodyLoad],
                stabilisation: #v2,
                cut: #v2,
                qdd: &mut #rt::nalgebra::SVector<f64, #dof>,
                joint_forces: &mut [#v2; #n],
                links: &mut [#elimination::LinkTerms; #n],
                joints: &mut [#elimination::JointTerms; #m],
            ) -> ::core::result::Result<(), #rt::DynamicsError> {
                const N: usize = #n;
                const M: usize = #m;
                #tables
                use #elimination::{Sweep, back};
                #link_pass
                #elimination_sweeps
                #forces_and_accelerations
            }
            let trig: &[(f64, f64); #n] = trig.try_into().expect("one (sin θ, cos θ) per link");
            let joint_forces: &mut [#v2; #n] =
                joint_forces.try_into().expect("one force per joint");
            ::core::assert!(
                loads.is_empty() || loads.len() == #n,
                "one load per link, or none"
            );
            #elimination::with_tables::<#n, #m, _>(|links, joints| match closing {
                #constrained
                #rt::ClosingJoint::Cut { force } => {
                    solve::<false>(trig, qd, loads, <#v2>::zeros(), force, qdd, joint_forces, links, joints)
                }
            })
        }
    }
}

/// The generated `solve`'s first pass: per link, independent of the
/// others, its levers, blocks and right-side terms (`LinkTerms`), and for
/// a cut loop the cut force's share of the two links beside the cut.
/// `inverse` holds `1/J` and `1/m` of the first and the last link.
fn link_pass(
    link_terms: &TokenStream,
    elimination: &TokenStream,
    inverse: [&TokenStream; 4],
) -> TokenStream {
    let [ij_first, im_first_cut, ij_last, im_last] = inverse;
    quote! {
        // Per link, independent of the others (vectorised): levers,
        // blocks and right-side terms.
        let mut force_first = [0.0f64; 2];
        let loaded = !loads.is_empty();
        for i in 0..N {
            let (s, c) = trig[i];
            let w = qd[2 + i];
            let (load_x, load_y, moment) = if loaded {
                let l = &loads[i];
                (l.force.x, l.force.y, l.moment)
            } else {
                (0.0, 0.0, 0.0)
            };
            #link_terms
            links[i] = #elimination::LinkTerms {
                p1: [p1x, p1y],
                p2: [p2x, p2y],
                moment,
                a2: link_a2,
                a1: link_a1,
                coupling: link_l,
                e2: link_e2,
                e1: link_e1,
            };
            if i == 0 {
                force_first = [fx, fy];
            }
        }
        if !CLOSED {
            // Across the cut: `cut` on link n at ū2ⁿ, reversed on
            // link 1 at ū1¹; their right-side terms change by
            // −(p ΔT/J + ΔF/m).
            let on_last = links[N - 1].p2[0] * cut.x + links[N - 1].p2[1] * cut.y;
            let on_first = -(links[0].p1[0] * cut.x + links[0].p1[1] * cut.y);
            {
                let link = &mut links[N - 1];
                let (dj, dm) = (#ij_last * on_last, #im_last);
                for (side, p) in [(&mut link.e2, link.p2), (&mut link.e1, link.p1)] {
                    side[0] -= p[0] * dj + cut.x * dm;
                    side[1] -= p[1] * dj + cut.y * dm;
                }
                link.moment += on_last;
            }
            {
                let link = &mut links[0];
                let (dj, dm) = (#ij_first * on_first, #im_first_cut);
                for (side, p) in [(&mut link.e2, link.p2), (&mut link.e1, link.p1)] {
                    side[0] -= p[0] * dj - cut.x * dm;
                    side[1] -= p[1] * dj - cut.y * dm;
                }
                link.moment += on_first;
            }
            force_first = [force_first[0] - cut.x, force_first[1] - cut.y];
        }
    }
}

/// The generated `solve`'s elimination of the joints' block-tridiagonal
/// system from both ends toward the middle joint, and the substitution
/// back outward; `row_j` builds joint `j`'s row.
fn elimination_sweeps(row_j: &TokenStream) -> TokenStream {
    quote! {
        // Twisted elimination ("burn at both ends"): joints 0 … h−1
        // eliminated downward and M−1 … h+1 upward, interleaved (two
        // independent chains for the processor to overlap), meeting
        // at joint h (the joints' terms: `JointTerms`).
        let h = M / 2;
        // Joints below h (the upward sweep): M − 1 − h ≤ h of them.
        let below = M.saturating_sub(1 + h);
        let mut down = Sweep::default();
        let mut up = Sweep::default();
        for t in 0..h {
            {
                let j = t;
                #row_j
                if j > 0 {
                    down.eliminate_into::<CLOSED>(true, links[j].coupling, &mut joints[j].fac, &mut d, &mut r, &mut z);
                }
                down.keep::<CLOSED>(j, d, r, z, &mut joints[j])?;
            }
            if t < below {
                let j = M - 1 - t;
                #row_j
                if j + 1 < M {
                    up.eliminate_into::<CLOSED>(false, links[j + 1].coupling, &mut joints[j + 1].fac, &mut d, &mut r, &mut z);
                }
                up.keep::<CLOSED>(j, d, r, z, &mut joints[j])?;
            }
        }
        if M > 0 {
            // The meeting joint takes both sweeps.
            let j = h;
            #row_j
            if j > 0 {
                down.eliminate_into::<CLOSED>(true, links[j].coupling, &mut joints[j].fac, &mut d, &mut r, &mut z);
            }
            if j + 1 < M {
                up.eliminate_into::<CLOSED>(false, links[j + 1].coupling, &mut joints[j + 1].fac, &mut d, &mut r, &mut z);
            }
            Sweep::default().keep::<CLOSED>(j, d, r, z, &mut joints[j])?;
        }
        // Outward from the meeting joint, both ways at once:
        // xⱼ = yⱼ − fac[l]ᵀ x_(neighbour nearer h).
        for t in 1..=h {
            let j = h - t;
            back::<CLOSED, M>(joints, j, j + 1);
            if t <= below {
                let j = h + t;
                back::<CLOSED, M>(joints, j, j - 1);
            }
        }
    }
}

/// The generated `solve`'s last steps: the closing joint's force (the
/// bordered system's Schur complement, or the cut force), every joint's
/// force, and the links' accelerations from them.
fn forces_and_accelerations(
    singular: &TokenStream,
    v2: &TokenStream,
    ij_i: &TokenStream,
    im_first: &TokenStream,
) -> TokenStream {
    quote! {
        // The closing joint's force: the Schur complement of the
        // bordered system, (C − Bᵀ Z) y = s − Bᵀ x.
        let closing = if CLOSED {
            let (a, b) = (links[N - 1].a2, links[0].a1);
            let (mut d00, mut d01, mut d11) = (a[0] + b[0], a[1] + b[1], a[2] + b[2]);
            let mut d10 = d01;
            let mut r = [
                links[N - 1].e2[0] - links[0].e1[0] - stabilisation.x,
                links[N - 1].e2[1] - links[0].e1[1] - stabilisation.y,
            ];
            // b₀ = L₁ at joint 0, b_m = L_nᵀ at joint n − 1, as
            // 2 × 2 row-major (b[2r + c]).
            let last = links[N - 1].coupling;
            for (b, at) in [(links[0].coupling, 0usize), ([last[0], last[2], last[1], last[3]], M.saturating_sub(1))] {
                let (z, x) = (joints[at].yz, joints[at].yr);
                d00 -= b[0] * z[0] + b[2] * z[2];
                d01 -= b[0] * z[1] + b[2] * z[3];
                d10 -= b[1] * z[0] + b[3] * z[2];
                d11 -= b[1] * z[1] + b[3] * z[3];
                r[0] -= b[0] * x[0] + b[2] * x[1];
                r[1] -= b[1] * x[0] + b[3] * x[1];
            }
            let det = d00 * d11 - d01 * d10;
            if !(det != 0.0 && det.is_finite()) {
                return ::core::result::Result::Err(#singular { joint: N - 1 });
            }
            <#v2>::new((d11 * r[0] - d01 * r[1]) / det, (d00 * r[1] - d10 * r[0]) / det)
        } else {
            cut
        };
        // Each joint's force λⱼ = xⱼ − Zⱼ y, then the accelerations
        // aᵢ = Wᵢ (Fᵢ + D⁺ᵢᵀ λᵢ − D⁻ᵢᵀ λᵢ₋₁).
        for j in 0..M {
            let (x, z) = (joints[j].yr, joints[j].yz);
            joint_forces[j] = if CLOSED {
                <#v2>::new(
                    x[0] - z[0] * closing.x - z[1] * closing.y,
                    x[1] - z[2] * closing.x - z[3] * closing.y,
                )
            } else {
                <#v2>::new(x[0], x[1])
            };
        }
        joint_forces[N - 1] = closing;
        // With the joint cut, its force acts through the loads.
        let acting = |j: usize| if CLOSED || j < M { joint_forces[j] } else { <#v2>::zeros() };
        for i in 0..N {
            let ahead = acting(i);
            let behind = acting((i + N - 1) % N);
            qdd[2 + i] = #ij_i
                * (links[i].moment + links[i].p2[0] * ahead.x + links[i].p2[1] * ahead.y
                    - links[i].p1[0] * behind.x - links[i].p1[1] * behind.y);
        }
        let (ahead, behind) = (acting(0), acting(N - 1));
        qdd[0] = #im_first * (force_first[0] + ahead.x - behind.x);
        qdd[1] = #im_first * (force_first[1] + ahead.y - behind.y);
        ::core::result::Result::Ok(())
    }
}
