//! The trees the generator works on, lowered from the declaration: the
//! track as a chain, the chassis as a frame with its parts and arms.

use crate::ir::{Link, Part, TreeBody};
use crate::num::{Num, Vec2};

/// The frame's local tag (the paper's superscript `c`).
const FRAME: &str = "chassis";

/// The chain as a tree: link `i` hangs from link `i − 1` by `ū1ⁱ` at
/// `ū2^{i−1}`; tags are the paper's link numbers `1 … n`.
pub fn chain(links: &[Link]) -> Vec<TreeBody> {
    links
        .iter()
        .enumerate()
        .map(|(i, link)| TreeBody {
            tag: (i + 1).to_string(),
            mass: link.mass.clone(),
            inertia: link.inertia.clone(),
            parent: i.checked_sub(1),
            at_parent: match i {
                0 => Vec2::zero(),
                _ => links[i - 1].u2.clone(),
            },
            at_self: match i {
                0 => Vec2::zero(),
                _ => link.u1.clone(),
            },
        })
        .collect()
}

/// The chassis as a two-level tree: the frame (body 0), then each part,
/// preceded by its arm if it has one; and the body index of each part and
/// of its arm. An arm's centroid is midway between its pivot and the part,
/// and its frame is aligned with the chassis at the design position.
pub fn chassis(
    mass: &Num,
    inertia: &Num,
    parts: &[Part],
) -> (Vec<TreeBody>, Vec<(usize, Option<usize>)>) {
    let mut bodies = vec![TreeBody {
        tag: FRAME.to_string(),
        mass: mass.clone(),
        inertia: inertia.clone(),
        parent: None,
        at_parent: Vec2::zero(),
        at_self: Vec2::zero(),
    }];
    let mut indices = Vec::with_capacity(parts.len());
    for part in parts {
        let (parent, at_parent, arm) = match &part.arm {
            Some(arm) => {
                // From the arm's centroid (midway) to the pivot and the part.
                let to_pivot = (arm.pivot.clone() - part.at.clone()).scale(&Num::Known(0.5));
                bodies.push(TreeBody {
                    tag: format!("{}_arm", part.name),
                    mass: arm.mass.clone(),
                    inertia: arm.inertia.clone(),
                    parent: Some(0),
                    at_parent: arm.pivot.clone(),
                    at_self: to_pivot.clone(),
                });
                let at = bodies.len() - 1;
                (at, -to_pivot, Some(at))
            }
            None => (0, part.at.clone(), None),
        };
        bodies.push(TreeBody {
            tag: part.name.to_string(),
            mass: part.mass.clone(),
            inertia: part.inertia.clone(),
            parent: Some(parent),
            at_parent,
            at_self: Vec2::zero(),
        });
        indices.push((bodies.len() - 1, arm));
    }
    (bodies, indices)
}
