//! `RecursiveModel::tree_dynamics` of a body tree (the chassis, formulation §3):
//! forward dynamics in O(n), generated and unrolled.
//!
//! Spec §5's route with the joint forces eliminated from the leaves: the
//! force `f_b` a body's parent puts on it at their joint is an affine
//! function of that joint point's acceleration `a_J`,
//! `f_b = K_b a_J + k_b`, whatever the subtree below does. With
//! `ρ_b = A_b ū_b` (the joint from the centroid), for each child `c` the
//! lever `λ_c = A_b w_{b→c}` from `b`'s joint to `c`'s and `u_c = perp(λ_c)`,
//! Newton-Euler for `b` (moments about its joint) gives its angular
//! acceleration as `α_b = g_b · a_J + h_b` with
//!
//! ```text
//! D_b = J_b + m_b |ū_b|² + Σ_c u_cᵀ K_c u_c
//! g_b = (m_b perp(ρ_b) − Σ_c K_c u_c) / D_b
//! h_b = (T_b − ρ_b × F_b − Σ_c u_c · β_c) / D_b,      β_c = k_c − ω_b² K_c λ_c
//! K_b = m_b I + Σ_c K_c − D_b g_b g_bᵀ
//! k_b = −D_b g_b h_b + m_b ω_b² ρ_b − F_b + Σ_c β_c
//! ```
//!
//! (a pinned wheel at its centroid has `K = m I`, `k = −F`, `α = T/J`).
//! The root, free, solves the 3 × 3 system of its centroid's acceleration
//! and `α_0`; then each child's joint acceleration
//! `a_c = a_J + α_b u_c − ω_b² λ_c` gives its `α_c`, down the tree. `F_b`,
//! `T_b` are the applied force (gravity included) and moment. Every
//! constant is folded and every structural zero dropped at compile time.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::lin::{Lin, LinVec};
use super::runtime_path::runtime;
use super::tree::Tree;
use crate::num::Num;

/// What the generated code knows of a body after its pass up the tree.
struct Up {
    /// `K_b` as (xx, xy, yy).
    k: [Lin; 3],
    /// `k_b`.
    bias: [Lin; 2],
    /// `g_b`, `None` when structurally zero.
    g: Option<[Lin; 2]>,
    /// `h_b`.
    h: Lin,
}

fn var(name: &str, tag: &str) -> Lin {
    let id = format_ident!("{}_{}", name, tag);
    Lin::var(quote!(#id))
}

fn bind(name: &str, tag: &str, value: &Lin) -> TokenStream {
    let id = format_ident!("{}_{}", name, tag);
    let t = value.tokens();
    quote!(let #id = #t;)
}

/// `K v` for `K` = (xx, xy, yy) and a run-time vector `v`.
fn times(k: &[Lin; 3], v: (&TokenStream, &TokenStream)) -> [Lin; 2] {
    let (x, y) = v;
    [
        k[0].clone().times(x).plus(k[1].clone().times(y)),
        k[1].clone().times(x).plus(k[2].clone().times(y)),
    ]
}

/// The statements of `tree_dynamics`, given `trig`, `qd`, `loads` (one per
/// body) and `qdd` in scope.
pub fn tree_dynamics(tree: &Tree) -> TokenStream {
    let rt = runtime();
    let n = tree.len();
    let mut out = TokenStream::new();
    // Per body: trig, rate, applied force and moment.
    for (b, body) in tree.bodies.iter().enumerate() {
        let tag = &body.tag;
        let (s, c) = (format_ident!("s_{}", tag), format_ident!("c_{}", tag));
        let (w, ww) = (format_ident!("w_{}", tag), format_ident!("ww_{}", tag));
        let i = 2 + b;
        let fx = Lin::constant(body.mass.clone() * tree.gravity.x.clone())
            .plus(Lin::var(quote!(loads[#b].force.x)));
        let fy = Lin::constant(body.mass.clone() * tree.gravity.y.clone())
            .plus(Lin::var(quote!(loads[#b].force.y)));
        let (fx, fy) = (bind("fx", tag, &fx), bind("fy", tag, &fy));
        out.extend(quote! {
            let (#s, #c) = trig[#b];
            let #w = qd[#i];
            let #ww = #w * #w;
            #fx
            #fy
        });
    }
    // Up the tree: children have larger indices than their parents.
    let mut up: Vec<Option<Up>> = (0..n).map(|_| None).collect();
    for b in (1..n).rev() {
        assert!(
            tree.bodies[b].parent.is_some_and(|p| p < b),
            "a tree's bodies come after their parents"
        );
        let (statements, result) = body_up(tree, b, &up);
        out.extend(statements);
        up[b] = Some(result);
    }
    out.extend(root(tree, &up, &rt));
    // Down the tree: each child's joint acceleration, then its α.
    for (b, u) in up.iter().enumerate().skip(1) {
        let tag = &tree.bodies[b].tag;
        let u = u.as_ref().expect("every body went up");
        let alpha = match &u.g {
            Some([gx, gy]) => gx
                .clone()
                .times(&var_tokens("ajx", tag))
                .plus(gy.clone().times(&var_tokens("ajy", tag)))
                .plus(u.h.clone()),
            None => u.h.clone(),
        };
        out.extend(bind("alpha", tag, &alpha));
        out.extend(joint_accelerations(tree, b));
        let a = format_ident!("alpha_{}", tag);
        let i = 2 + b;
        out.extend(quote!(qdd[#i] = #a;));
    }
    out
}

fn var_tokens(name: &str, tag: &str) -> TokenStream {
    let id = format_ident!("{}_{}", name, tag);
    quote!(#id)
}

/// The lever from body `b`'s joint to child `c`'s, `λ_c = A_b w_{b→c}`,
/// bound as `lx_c`, `ly_c`; and `u_c = perp(λ_c)` as `ux_c`, `uy_c`.
fn lever(tree: &Tree, b: usize, c: usize) -> TokenStream {
    let tag = &tree.bodies[c].tag;
    let lambda = tree.trig(b).rotate(&tree.lever(b, c));
    let (lx, ly) = (lambda.x.tokens(), lambda.y.tokens());
    let names = ["lx", "ly", "ux", "uy"].map(|p| format_ident!("{}_{}", p, tag));
    let [nlx, nly, nux, nuy] = &names;
    quote! {
        let #nlx = #lx;
        let #nly = #ly;
        let #nux = -#nly;
        let #nuy = #nlx;
    }
}

/// What child `c` adds to its parent's sums: its lever `u_c`, and `K_c u_c`
/// and `β_c = k_c − ω_b² K_c λ_c`, bound.
struct Child {
    ux: TokenStream,
    uy: TokenStream,
    kux: Lin,
    kuy: Lin,
    betax: Lin,
    betay: Lin,
}

/// Binds child `c`'s lever from `b` (whose `ω_b²` is `ww`) and its terms
/// ([`Child`]) into `out`.
fn child_terms(
    tree: &Tree,
    b: usize,
    c: usize,
    child: &Up,
    ww: &TokenStream,
    out: &mut TokenStream,
) -> Child {
    let ctag = &tree.bodies[c].tag;
    out.extend(lever(tree, b, c));
    let (ux, uy) = (var_tokens("ux", ctag), var_tokens("uy", ctag));
    let (lx, ly) = (var_tokens("lx", ctag), var_tokens("ly", ctag));
    let ku = times(&child.k, (&ux, &uy));
    let kl = times(&child.k, (&lx, &ly));
    out.extend(bind("kux", ctag, &ku[0]));
    out.extend(bind("kuy", ctag, &ku[1]));
    let beta = [
        child.bias[0].clone().minus(kl[0].clone().times(ww)),
        child.bias[1].clone().minus(kl[1].clone().times(ww)),
    ];
    out.extend(bind("betax", ctag, &beta[0]));
    out.extend(bind("betay", ctag, &beta[1]));
    Child {
        ux,
        uy,
        kux: var("kux", ctag),
        kuy: var("kuy", ctag),
        betax: var("betax", ctag),
        betay: var("betay", ctag),
    }
}

/// Body `b`'s pass up: its statements and what they bind.
fn body_up(tree: &Tree, b: usize, up: &[Option<Up>]) -> (TokenStream, Up) {
    let body = &tree.bodies[b];
    let tag = &body.tag;
    let children = tree.children(b);
    let (fx, fy) = (var("fx", tag), var("fy", tag));
    let moment = Lin::var(quote!(loads[#b].moment));
    let ww = var_tokens("ww", tag);
    let lever_free = body.at_self.is_zero();
    if children.is_empty() && lever_free {
        // A wheel pinned at its centroid: it turns freely about the pin.
        let h = moment.scaled(&(Num::Known(1.0) / body.inertia.clone()));
        let result = Up {
            k: [
                Lin::constant(body.mass.clone()),
                Lin::zero(),
                Lin::constant(body.mass.clone()),
            ],
            bias: [fx.scaled(&Num::Known(-1.0)), fy.scaled(&Num::Known(-1.0))],
            g: None,
            h,
        };
        return (TokenStream::new(), result);
    }
    let mut out = TokenStream::new();
    // ρ_b = A_b ū_b.
    let rho = tree.trig(b).rotate(&body.at_self);
    out.extend(rho.bind(&(format_ident!("rx_{}", tag), format_ident!("ry_{}", tag))));
    let rho = LinVec::vars(&(format_ident!("rx_{}", tag), format_ident!("ry_{}", tag)));
    // Sums over the children.
    let mut d =
        Lin::constant(body.inertia.clone() + body.mass.clone() * body.at_self.norm_squared());
    let mut g = [
        rho.y.clone().scaled(&-body.mass.clone()),
        rho.x.clone().scaled(&body.mass),
    ];
    let mut h = moment
        .minus(rho.x.clone().times(&var_tokens("fy", tag)))
        .plus(rho.y.clone().times(&var_tokens("fx", tag)));
    let mut k = [
        Lin::constant(body.mass.clone()),
        Lin::zero(),
        Lin::constant(body.mass.clone()),
    ];
    let mut bias = [
        rho.x.clone().scaled(&body.mass).times(&ww).minus(fx),
        rho.y.clone().scaled(&body.mass).times(&ww).minus(fy),
    ];
    for &c in children {
        let child = up[c].as_ref().expect("children go up first");
        let Child {
            ux,
            uy,
            kux,
            kuy,
            betax,
            betay,
        } = child_terms(tree, b, c, child, &ww, &mut out);
        d = d.plus(kux.clone().times(&ux)).plus(kuy.clone().times(&uy));
        g = [
            g[0].clone().minus(kux.clone()),
            g[1].clone().minus(kuy.clone()),
        ];
        h = h
            .minus(betax.clone().times(&ux))
            .minus(betay.clone().times(&uy));
        k = [
            k[0].clone().plus(child.k[0].clone()),
            k[1].clone().plus(child.k[1].clone()),
            k[2].clone().plus(child.k[2].clone()),
        ];
        bias = [bias[0].clone().plus(betax), bias[1].clone().plus(betay)];
    }
    // α_b = g · a_J + h, with D g and D h bound first; K_b and k_b.
    out.extend(bind("d", tag, &d));
    out.extend(bind("dgx", tag, &g[0]));
    out.extend(bind("dgy", tag, &g[1]));
    out.extend(bind("dh", tag, &h));
    let (d, dgx, dgy, dh) = (
        var_tokens("d", tag),
        var_tokens("dgx", tag),
        var_tokens("dgy", tag),
        var_tokens("dh", tag),
    );
    let names = ["gx", "gy", "h"].map(|p| format_ident!("{}_{}", p, tag));
    let [ngx, ngy, nh] = &names;
    out.extend(quote! {
        let #ngx = #dgx / #d;
        let #ngy = #dgy / #d;
        let #nh = #dh / #d;
    });
    let (gx, gy, hv) = (
        var_tokens("gx", tag),
        var_tokens("gy", tag),
        var_tokens("h", tag),
    );
    let kk = [
        k[0].clone().minus(Lin::var(quote!(#gx * #dgx))),
        k[1].clone().minus(Lin::var(quote!(#gx * #dgy))),
        k[2].clone().minus(Lin::var(quote!(#gy * #dgy))),
    ];
    let kb = [
        bias[0].clone().minus(Lin::var(quote!(#dgx * #hv))),
        bias[1].clone().minus(Lin::var(quote!(#dgy * #hv))),
    ];
    out.extend(bind("kxx", tag, &kk[0]));
    out.extend(bind("kxy", tag, &kk[1]));
    out.extend(bind("kyy", tag, &kk[2]));
    out.extend(bind("kx", tag, &kb[0]));
    out.extend(bind("ky", tag, &kb[1]));
    let result = Up {
        k: [var("kxx", tag), var("kxy", tag), var("kyy", tag)],
        bias: [var("kx", tag), var("ky", tag)],
        g: Some([var("gx", tag), var("gy", tag)]),
        h: var("h", tag),
    };
    (out, result)
}

/// The root's 3 × 3 solve for its centroid's acceleration and `α_0`.
fn root(tree: &Tree, up: &[Option<Up>], rt: &TokenStream) -> TokenStream {
    let body = &tree.bodies[0];
    let tag = &body.tag;
    let ww = var_tokens("ww", tag);
    let mut out = TokenStream::new();
    let mut a = [
        Lin::constant(body.mass.clone()),
        Lin::zero(),
        Lin::constant(body.mass.clone()),
    ];
    let (mut a02, mut a12) = (Lin::zero(), Lin::zero());
    let mut a22 = Lin::constant(body.inertia.clone());
    let mut r = [
        var("fx", tag),
        var("fy", tag),
        Lin::var(quote!(loads[0usize].moment)),
    ];
    for &c in tree.children(0) {
        let child = up[c].as_ref().expect("children go up first");
        let Child {
            ux,
            uy,
            kux,
            kuy,
            betax,
            betay,
        } = child_terms(tree, 0, c, child, &ww, &mut out);
        a = [
            a[0].clone().plus(child.k[0].clone()),
            a[1].clone().plus(child.k[1].clone()),
            a[2].clone().plus(child.k[2].clone()),
        ];
        a02 = a02.plus(kux.clone());
        a12 = a12.plus(kuy.clone());
        a22 = a22.plus(kux.times(&ux)).plus(kuy.times(&uy));
        r = [
            r[0].clone().minus(betax.clone()),
            r[1].clone().minus(betay.clone()),
            r[2].clone().minus(betax.times(&ux)).minus(betay.times(&uy)),
        ];
    }
    let t = |l: &Lin| {
        let t = l.tokens();
        quote!((#t))
    };
    let (a00, a01, a11) = (t(&a[0]), t(&a[1]), t(&a[2]));
    let (a02, a12, a22) = (t(&a02), t(&a12), t(&a22));
    let (r0, r1, r2) = (t(&r[0]), t(&r[1]), t(&r[2]));
    let (ajx, ajy, alpha) = (
        format_ident!("ajx_{}", tag),
        format_ident!("ajy_{}", tag),
        format_ident!("alpha_{}", tag),
    );
    out.extend(quote! {
        // The root: [m I + Σ K, Σ K u; (Σ K u)ᵀ, J + Σ uᵀ K u] [R̈; α] = r,
        // symmetric positive definite, by cofactors.
        let (a00, a01, a02, a11, a12, a22) = (#a00, #a01, #a02, #a11, #a12, #a22);
        let (r0, r1, r2) = (#r0, #r1, #r2);
        let (c00, c01, c02) = (a11 * a22 - a12 * a12, a02 * a12 - a01 * a22, a01 * a12 - a02 * a11);
        let det = a00 * c00 + a01 * c01 + a02 * c02;
        if !(det > 0.0 && det.is_finite()) {
            return ::core::result::Result::Err(#rt::DynamicsError::MassMatrixNotPositiveDefinite);
        }
        let (c11, c12, c22) = (a00 * a22 - a02 * a02, a01 * a02 - a00 * a12, a00 * a11 - a01 * a01);
        let #ajx = (c00 * r0 + c01 * r1 + c02 * r2) / det;
        let #ajy = (c01 * r0 + c11 * r1 + c12 * r2) / det;
        let #alpha = (c02 * r0 + c12 * r1 + c22 * r2) / det;
        qdd[0] = #ajx;
        qdd[1] = #ajy;
        qdd[2] = #alpha;
    });
    out.extend(joint_accelerations(tree, 0));
    out
}

/// Each child `c` of `b`: its joint's acceleration
/// `a_c = a_J + α_b u_c − ω_b² λ_c`, bound as `ajx_c`, `ajy_c`.
fn joint_accelerations(tree: &Tree, b: usize) -> TokenStream {
    let tag = &tree.bodies[b].tag;
    let (ajx, ajy, alpha, ww) = (
        var_tokens("ajx", tag),
        var_tokens("ajy", tag),
        var_tokens("alpha", tag),
        var_tokens("ww", tag),
    );
    tree.children(b)
        .iter()
        .map(|&c| {
            let ctag = &tree.bodies[c].tag;
            let (ux, uy, lx, ly) = (
                var_tokens("ux", ctag),
                var_tokens("uy", ctag),
                var_tokens("lx", ctag),
                var_tokens("ly", ctag),
            );
            let (cx, cy) = (format_ident!("ajx_{}", ctag), format_ident!("ajy_{}", ctag));
            quote! {
                let #cx = #ajx + #alpha * #ux - #ww * #lx;
                let #cy = #ajy + #alpha * #uy - #ww * #ly;
            }
        })
        .collect()
}
