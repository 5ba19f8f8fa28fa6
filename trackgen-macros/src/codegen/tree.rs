//! `RecursiveModel` for a tree of bodies in recursive coordinates: one
//! generator for the track (a chain, formulation §1) and the chassis (a frame with
//! pinned parts, formulation §3).
//!
//! Body `b` hangs from its parent `p` by a revolute joint:
//! `Rᵇ = Rᵖ + Aᵖ ū_p − Aᵇ ū_b`. Writing `w_{p→b} = ū_p − ū_{p's own joint}`
//! (formulation §1's `c_j`: `ū2¹`, then `d̄ʲ`), every closed form of formulation §1
//! generalises from a chain to a tree with subtree sums in place of the
//! suffix sums `S_k`:
//!
//! ```text
//! Sᵇ      = mᵇ + Σ_children S^c                              (subtree mass)
//! ēᵇ      = Σ_c S^c w_{b→c} − mᵇ ū_b ,   eᵇ = A_θᵇ ēᵇ        (= M_Rθb)
//! M_θbθb  = Jᵇ + mᵇ|ū_b|² + Σ_c S^c |w_{b→c}|²                (a constant)
//! M_θjθk  = (A_θʲ w_{j→next}) · eᵏ   for j an ancestor of k, else 0
//! Q_θb    = Σ_c (A_θᵇ w_{b→c}) · Φ^c − (A_θᵇ ū_b) · F̃ᵇ + Tᵇ,  Φ = subtree sum of F̃
//! ```
//!
//! For a chain these are exactly formulation §1's `M_Rθj = S_{j+1} b_j − m_j a_j`,
//! `M_θjθk = S_{k+1} b_j·b_k − m_k b_j·a_k` and `Q_θj`.

use proc_macro2::{Ident, TokenStream};
use quote::{format_ident, quote};

use super::lin::{Lin, LinVec, Trig, pair};
use crate::num::{Num, Vec2};

/// One body of a tree to generate: the IR's.
pub use crate::ir::TreeBody as Body;

/// The spring-damper of a penalty-closed track: it acts along the closure
/// gap `C = Σ Aʲ d̄ʲ`, so `Q_i` gains `C_qᵀ F` with `F = −k C − c Ċ`.
pub struct Penalty {
    pub stiffness: Num,
    pub damping: Num,
    /// `d̄ʲ` of every link.
    pub spans: Vec<Vec2>,
}

/// A tree and everything derived from it at compile time.
pub struct Tree {
    pub bodies: Vec<Body>,
    pub gravity: Vec2,
    pub penalty: Option<Penalty>,
    children: Vec<Vec<usize>>,
    subtree_mass: Vec<Num>,
    moment: Vec<Vec2>,
    diagonal: Vec<Num>,
}

impl Tree {
    pub fn new(bodies: Vec<Body>, gravity: Vec2, penalty: Option<Penalty>) -> Tree {
        let n = bodies.len();
        let mut children = vec![Vec::new(); n];
        for (b, body) in bodies.iter().enumerate() {
            if let Some(p) = body.parent {
                children[p].push(b);
            }
        }
        let mut subtree_mass = vec![Num::ZERO; n];
        let mut moment = vec![Vec2::zero(); n];
        let mut diagonal = vec![Num::ZERO; n];
        let mut tree = Tree {
            bodies,
            gravity,
            penalty,
            children,
            subtree_mass: Vec::new(),
            moment: Vec::new(),
            diagonal: Vec::new(),
        };
        for b in (0..n).rev() {
            let body = &tree.bodies[b];
            let mut s = body.mass.clone();
            let mut e = -body.at_self.scale(&body.mass);
            let mut d = body.inertia.clone() + body.mass.clone() * body.at_self.norm_squared();
            for &c in &tree.children[b] {
                let w = tree.lever(b, c);
                s = s + subtree_mass[c].clone();
                e = e + w.scale(&subtree_mass[c]);
                d = d + subtree_mass[c].clone() * w.norm_squared();
            }
            subtree_mass[b] = s;
            moment[b] = e;
            diagonal[b] = d;
        }
        tree.subtree_mass = subtree_mass;
        tree.moment = moment;
        tree.diagonal = diagonal;
        tree
    }

    pub fn len(&self) -> usize {
        self.bodies.len()
    }

    /// The bodies hanging from body `b`.
    pub fn children(&self, b: usize) -> &[usize] {
        &self.children[b]
    }

    /// `w_{b→c}`: from `b`'s own joint to its child `c`'s, in `b`'s frame.
    pub fn lever(&self, b: usize, c: usize) -> Vec2 {
        self.bodies[c].at_parent.clone() - self.bodies[b].at_self.clone()
    }

    pub fn trig(&self, b: usize) -> Trig {
        Trig::new(&self.bodies[b].tag)
    }

    /// Every body's angle's sine and cosine once, by the runtime's
    /// vectorised `sin_cos_each` into `trig`, then
    /// `let (s_b, c_b) = trig[b];`.
    pub fn trig_prelude(&self) -> TokenStream {
        let rt = super::runtime_path::runtime();
        let (n, from_slice) = (self.len(), self.trig_from_slice());
        quote! {
            let mut trig = [(0.0f64, 1.0f64); #n];
            #rt::sin_cos_each(&q.as_slice()[2..], &mut trig);
            #from_slice
        }
    }

    /// `let (s_b, c_b) = trig[b];`: the same locals from a caller's slice.
    pub fn trig_from_slice(&self) -> TokenStream {
        self.bodies
            .iter()
            .enumerate()
            .map(|(b, body)| {
                let Trig { s, c } = Trig::new(&body.tag);
                quote! { let (#s, #c) = trig[#b]; }
            })
            .collect()
    }

    /// `let w_b = qd[2 + b];` (and `ww_b = w_b²` when asked).
    pub fn rate_prelude(&self, squares: bool) -> TokenStream {
        self.bodies
            .iter()
            .enumerate()
            .map(|(b, body)| {
                let w = format_ident!("w_{}", body.tag);
                let ww = format_ident!("ww_{}", body.tag);
                let i = 2 + b;
                if squares {
                    quote! { let #w = qd[#i]; let #ww = #w * #w; }
                } else {
                    quote! { let #w = qd[#i]; }
                }
            })
            .collect()
    }

    fn w(&self, b: usize) -> TokenStream {
        let w = format_ident!("w_{}", self.bodies[b].tag);
        quote!(#w)
    }

    fn ww(&self, b: usize) -> TokenStream {
        let w = format_ident!("ww_{}", self.bodies[b].tag);
        quote!(#w)
    }

    /// A top-down recursion `xᵇ = xᵖ + step(p, b)`, root value given; binds
    /// `{prefix}x_b`, `{prefix}y_b`.
    fn top_down(
        &self,
        prefix: &str,
        root: LinVec,
        step: impl Fn(usize, usize) -> LinVec,
    ) -> TokenStream {
        let mut out = TokenStream::new();
        for (b, body) in self.bodies.iter().enumerate() {
            let value = match body.parent {
                None => root.clone(),
                Some(p) => {
                    let parent = LinVec::vars(&pair(prefix, &self.bodies[p].tag));
                    let parent = if self.is_zero_var(prefix, p) {
                        LinVec::zero()
                    } else {
                        parent
                    };
                    parent.plus(step(p, b))
                }
            };
            out.extend(value.bind(&pair(prefix, &body.tag)));
        }
        out
    }

    /// The root's `γ` is identically zero; skip it in sums.
    fn is_zero_var(&self, prefix: &str, b: usize) -> bool {
        prefix == "g" && self.bodies[b].parent.is_none()
    }

    /// Positions, eq. (4) / (8): binds `rx_b`, `ry_b`.
    pub fn positions(&self) -> TokenStream {
        self.top_down(
            "r",
            LinVec {
                x: Lin::var(quote!(q[0])),
                y: Lin::var(quote!(q[1])),
            },
            |p, b| {
                self.trig(p)
                    .rotate(&self.bodies[b].at_parent)
                    .minus(self.trig(b).rotate(&self.bodies[b].at_self))
            },
        )
    }

    /// Velocities, the structured product `H̄₁ H̄ₙ q̇_i` of eq. (7): binds
    /// `vx_b`, `vy_b`.
    pub fn velocities(&self) -> TokenStream {
        self.top_down(
            "v",
            LinVec {
                x: Lin::var(quote!(qd[0])),
                y: Lin::var(quote!(qd[1])),
            },
            |p, b| {
                let from_parent = self
                    .trig(p)
                    .rotate_derivative(&self.bodies[b].at_parent)
                    .times(&self.w(p));
                let own = self
                    .trig(b)
                    .rotate_derivative(&self.bodies[b].at_self)
                    .times(&self.w(b));
                from_parent.minus(own)
            },
        )
    }

    /// `γ_R`, eq. (14): `γᵇ = γᵖ − Aᵖ ū_p ωₚ² + Aᵇ ū_b ωᵇ²`; binds `gx_b`,
    /// `gy_b` (the root's is zero).
    pub fn velocity_terms(&self) -> TokenStream {
        self.top_down("g", LinVec::zero(), |p, b| {
            let from_parent = self
                .trig(p)
                .rotate(&self.bodies[b].at_parent)
                .times(&self.ww(p));
            let own = self
                .trig(b)
                .rotate(&self.bodies[b].at_self)
                .times(&self.ww(b));
            own.minus(from_parent)
        })
    }

    /// `a_b = A_θᵇ ū_b` where `ū_b ≠ 0`.
    fn own_lever(&self, b: usize) -> LinVec {
        self.trig(b).rotate_derivative(&self.bodies[b].at_self)
    }

    /// The local naming `A_θᵇ w_{b→c}` (`b_j` of formulation §1).
    fn lever_names(&self, b: usize, c: usize) -> (Ident, Ident) {
        if self.children[b].len() == 1 {
            pair("b", &self.bodies[b].tag)
        } else {
            pair(
                "b",
                &format!("{}_{}", self.bodies[b].tag, self.bodies[c].tag),
            )
        }
    }

    /// Binds `bx_…` for every non-zero lever and `ex_b = A_θᵇ ēᵇ` for every
    /// non-zero first moment.
    fn lever_bindings(&self, with_moments: bool) -> TokenStream {
        let mut out = TokenStream::new();
        for b in 0..self.len() {
            for &c in &self.children[b] {
                let lever = self.lever(b, c);
                if !lever.is_zero() {
                    out.extend(
                        self.trig(b)
                            .rotate_derivative(&lever)
                            .bind(&self.lever_names(b, c)),
                    );
                }
            }
            if with_moments && !self.moment[b].is_zero() {
                out.extend(
                    self.trig(b)
                        .rotate_derivative(&self.moment[b])
                        .bind(&pair("e", &self.bodies[b].tag)),
                );
            }
        }
        out
    }

    fn lever_var(&self, b: usize, c: usize) -> Option<LinVec> {
        (!self.lever(b, c).is_zero()).then(|| LinVec::vars(&self.lever_names(b, c)))
    }

    /// The child of `j` on the path to its descendant `k`, if `j` is a
    /// strict ancestor of `k`.
    fn next_on_path(&self, j: usize, k: usize) -> Option<usize> {
        let mut node = k;
        while let Some(p) = self.bodies[node].parent {
            if p == j {
                return Some(node);
            }
            node = p;
        }
        None
    }

    /// Fills `out` (the `M_i` matrix) from the closed forms.
    pub fn mass_matrix(&self) -> TokenStream {
        let n = self.len();
        let mut out = self.lever_bindings(true);
        let s = &self.subtree_mass[0];
        out.extend(quote! {
            out[(0, 0)] = #s; out[(1, 1)] = #s; out[(0, 1)] = 0.0; out[(1, 0)] = 0.0;
        });
        for k in 0..n {
            let col = 2 + k;
            let (ex, ey) = if self.moment[k].is_zero() {
                (quote!(0.0), quote!(0.0))
            } else {
                let (x, y) = pair("e", &self.bodies[k].tag);
                (quote!(#x), quote!(#y))
            };
            out.extend(quote! {
                out[(0, #col)] = #ex; out[(#col, 0)] = #ex; out[(1, #col)] = #ey; out[(#col, 1)] = #ey;
            });
            let d = &self.diagonal[k];
            out.extend(quote! { out[(#col, #col)] = #d; });
        }
        if self.is_chain() && n > 1 {
            out.extend(self.chain_coupling());
            return out;
        }
        for k in 0..n {
            for j in 0..k {
                let (r, c) = (2 + j, 2 + k);
                let value = match (self.next_on_path(j, k), self.moment[k].is_zero()) {
                    (Some(next), false) => match self.lever_var(j, next) {
                        Some(lever) => dot(&lever, &LinVec::vars(&pair("e", &self.bodies[k].tag))),
                        None => quote!(0.0),
                    },
                    _ => quote!(0.0),
                };
                out.extend(quote! { out[(#r, #c)] = #value; out[(#c, #r)] = out[(#r, #c)]; });
            }
        }
        out
    }

    /// Whether body `b` hangs from body `b − 1`, for every `b`.
    fn is_chain(&self) -> bool {
        self.bodies
            .iter()
            .enumerate()
            .all(|(b, body)| body.parent == b.checked_sub(1))
    }

    /// A chain's `M_θjθk = b_j · e_k` (j < k) is an outer product of two
    /// O(n) lists in which every constant is already folded. The O(n²) fill
    /// is therefore a loop: unrolling it would fold nothing more, and would
    /// cost n²/2 statements of compile time (8 256 at 128 links).
    fn chain_coupling(&self) -> TokenStream {
        let n = self.len();
        let vars = |v: Option<(Ident, Ident)>| match v {
            Some((x, y)) => quote!((#x, #y)),
            None => quote!((0.0, 0.0)),
        };
        let levers =
            (0..n - 1).map(|j| vars(self.lever_var(j, j + 1).map(|_| self.lever_names(j, j + 1))));
        let moments = (1..n)
            .map(|k| vars((!self.moment[k].is_zero()).then(|| pair("e", &self.bodies[k].tag))));
        quote! {
            let levers: [(f64, f64); #n - 1] = [#(#levers),*];
            let moments: [(f64, f64); #n - 1] = [#(#moments),*];
            for k in 1..#n {
                let (ex, ey) = moments[k - 1];
                for j in 0..k {
                    let (bx, by) = levers[j];
                    let coupling = bx * ex + by * ey;
                    out[(2 + j, 2 + k)] = coupling;
                    out[(2 + k, 2 + j)] = coupling;
                }
            }
        }
    }

    /// Fills `out` (`Q_i`) in O(n): `γ` top-down, `F̃ = F − m γ`, subtree
    /// force sums `Φ` bottom-up, then one dot product per lever. Expects
    /// `loads: &[BodyLoad]` with one entry per body.
    pub fn generalized_forces(&self) -> TokenStream {
        let n = self.len();
        let mut out = self.rate_prelude(true);
        out.extend(self.velocity_terms());
        out.extend(self.lever_bindings(false));
        for (b, body) in self.bodies.iter().enumerate() {
            let (gx, gy) = pair("g", &body.tag);
            let g = if body.parent.is_none() {
                LinVec::zero()
            } else {
                LinVec::vars(&(gx, gy))
            };
            let i = b;
            let applied = LinVec {
                x: Lin::var(quote!(loads[#i].force.x)),
                y: Lin::var(quote!(loads[#i].force.y)),
            };
            let f = LinVec::constant(&self.gravity.scale(&body.mass))
                .minus(g.scaled(&body.mass))
                .plus(applied);
            out.extend(f.bind(&pair("f", &body.tag)));
        }
        for b in (0..n).rev() {
            let mut phi = LinVec::vars(&pair("f", &self.bodies[b].tag));
            for &c in &self.children[b] {
                phi = phi.plus(LinVec::vars(&pair("p", &self.bodies[c].tag)));
            }
            out.extend(phi.bind(&pair("p", &self.bodies[b].tag)));
        }
        let (px, py) = pair("p", &self.bodies[0].tag);
        out.extend(quote! { out[0] = #px; out[1] = #py; });
        for b in 0..n {
            let mut terms = Vec::new();
            for &c in &self.children[b] {
                if let Some(lever) = self.lever_var(b, c) {
                    terms.push(dot(&lever, &LinVec::vars(&pair("p", &self.bodies[c].tag))));
                }
            }
            if !self.bodies[b].at_self.is_zero() {
                let a = self.own_lever(b);
                let f = LinVec::vars(&pair("f", &self.bodies[b].tag));
                let (ax, ay) = (a.x.tokens(), a.y.tokens());
                let (fx, fy) = (f.x.tokens(), f.y.tokens());
                terms.push(quote!(-((#ax) * #fx + (#ay) * #fy)));
            }
            let i = b;
            terms.push(quote!(loads[#i].moment));
            let row = 2 + b;
            out.extend(quote! { out[#row] = #(#terms)+*; });
        }
        if let Some(penalty) = &self.penalty {
            out.extend(self.penalty_forces(penalty));
        }
        out
    }

    /// `Q_i += C_qᵀ F`, `F = −k C − c Ċ` (formulation §2, secondary joint).
    fn penalty_forces(&self, penalty: &Penalty) -> TokenStream {
        let mut out = TokenStream::new();
        let mut gap = LinVec::zero();
        let mut rate = LinVec::zero();
        for (j, span) in penalty.spans.iter().enumerate() {
            let names = pair("k", &self.bodies[j].tag);
            out.extend(self.trig(j).rotate_derivative(span).bind(&names));
            gap = gap.plus(self.trig(j).rotate(span));
            rate = rate.plus(LinVec::vars(&names).times(&self.w(j)));
        }
        out.extend(gap.bind(&(format_ident!("gap_x"), format_ident!("gap_y"))));
        out.extend(rate.bind(&(format_ident!("rate_x"), format_ident!("rate_y"))));
        let (k, c) = (&penalty.stiffness, &penalty.damping);
        let rt = super::runtime_path::runtime();
        // The runtime's law, the one owner of `F = −k C − c Ċ`.
        out.extend(quote! {
            let pen = #rt::PenaltyJoint { stiffness: #k, damping: #c }.force(
                #rt::nalgebra::Vector2::new(gap_x, gap_y),
                #rt::nalgebra::Vector2::new(rate_x, rate_y),
            );
            let (pen_x, pen_y) = (pen.x, pen.y);
        });
        for j in 0..penalty.spans.len() {
            let (kx, ky) = pair("k", &self.bodies[j].tag);
            let row = 2 + j;
            out.extend(quote! { out[#row] += #kx * pen_x + #ky * pen_y; });
        }
        out
    }

    /// `Σ ½ mᵇ |Ṙᵇ|² + ½ Jᵇ ωᵇ²`, with the velocities bound.
    pub fn kinetic_energy(&self) -> TokenStream {
        let terms = self.bodies.iter().map(|body| {
            let (vx, vy) = pair("v", &body.tag);
            let w = format_ident!("w_{}", body.tag);
            let (m, j) = (&body.mass, &body.inertia);
            quote!(#m * (#vx * #vx + #vy * #vy) + #j * (#w * #w))
        });
        quote! { 0.5 * (#(#terms)+*) }
    }

    /// `−Σ mᵇ g·Rᵇ`, with the positions bound.
    pub fn gravity_potential(&self) -> TokenStream {
        let mut lin = Lin::zero();
        for body in &self.bodies {
            let (rx, ry) = pair("r", &body.tag);
            lin = lin
                .minus(Lin::term(
                    body.mass.clone() * self.gravity.x.clone(),
                    quote!(#rx),
                ))
                .minus(Lin::term(
                    body.mass.clone() * self.gravity.y.clone(),
                    quote!(#ry),
                ));
        }
        lin.tokens()
    }

    /// Rows into the output slice: `out[b] = Vector2::new({prefix}x_b, …)`.
    pub fn store(&self, prefix: &str, rt: &TokenStream) -> TokenStream {
        self.bodies
            .iter()
            .enumerate()
            .map(|(b, body)| {
                let (x, y) = pair(prefix, &body.tag);
                quote! { out[#b] = #rt::nalgebra::Vector2::new(#x, #y); }
            })
            .collect()
    }

    /// The `TreeDescription` literal.
    pub fn description(&self, rt: &TokenStream, loop_joint: TokenStream) -> TokenStream {
        let bodies = self.bodies.iter().map(|b| {
            let (m, j) = (&b.mass, &b.inertia);
            let parent = match b.parent {
                Some(p) => quote!(::core::option::Option::Some(#p)),
                None => quote!(::core::option::Option::None),
            };
            let (px, py, sx, sy) = (&b.at_parent.x, &b.at_parent.y, &b.at_self.x, &b.at_self.y);
            quote! {
                #rt::BodyDescription {
                    mass: #m, inertia: #j, parent: #parent,
                    at_parent: #rt::nalgebra::Vector2::new(#px, #py),
                    at_self: #rt::nalgebra::Vector2::new(#sx, #sy),
                }
            }
        });
        let (gx, gy) = (&self.gravity.x, &self.gravity.y);
        quote! {
            #rt::TreeDescription {
                bodies: ::std::vec![#(#bodies),*],
                gravity: #rt::nalgebra::Vector2::new(#gx, #gy),
                loop_joint: #loop_joint,
            }
        }
    }
}

/// `a · b` of two run-time vectors held in locals.
fn dot(a: &LinVec, b: &LinVec) -> TokenStream {
    let (ax, ay, bx, by) = (a.x.tokens(), a.y.tokens(), b.x.tokens(), b.y.tokens());
    quote!(#ax * #bx + #ay * #by)
}
