//! Placing a spatial vehicle's two sides at t = 0: the hull (its frame
//! and both sides' running gear, one planar tree) on the ground at its
//! design position, each side's tensioner set to take up its own track's
//! slack, each track wrapped round its own side's wheels and each
//! sprocket turned so that a gap holds a joint: [`assemble`]'s recipe,
//! once per side, with the hull lowered once for both.
//!
//! Every coordinate is planar: the hull's and each track's `q_i` in their
//! planes, which stand upright at the hull's centre line and half a gauge
//! to either side ([`SpatialLayout`](crate::spatial::SpatialLayout)).
//!
//! [`assemble`]: super::assemble

use nalgebra::SVector;
use thiserror::Error;

use super::AssemblyError;
use super::vehicle::{Gear, check_start};
use crate::contact::ShoeGeometry;
use crate::contact::sprocket::ToothProfile;
use crate::multibody::{ChassisModel, ChassisPart, TrackModel};
use crate::spatial::Side;
use crate::terrain::Terrain;

/// Initial coordinates of a spatial vehicle's hull and tracks, each in its
/// own plane.
#[derive(Debug, Clone, PartialEq)]
pub struct AssembledSides<const DH: usize, const DR: usize, const DL: usize> {
    /// The hull's `q_i`: the frame's centroid and angle, both sides' arms
    /// and parts.
    pub hull: SVector<f64, DH>,
    /// The right track's `q_i`.
    pub right: SVector<f64, DR>,
    /// The left track's `q_i`.
    pub left: SVector<f64, DL>,
    /// Each side's tensioner as set (right, left): its arm's body in the
    /// hull and its angle, rad from the declared position.
    pub tensioners: [Option<(usize, f64)>; 2],
}

/// A side that would not assemble, and why.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("the {} side: {error}", match side { Side::Left => "left", Side::Right => "right" })]
pub struct SideError {
    /// The side.
    pub side: Side,
    /// What went wrong there.
    #[source]
    pub error: AssemblyError,
}

/// Assembles a spatial vehicle with its hull's centroid at `x` (m) and
/// each track `clearance` (m) above the terrain (the lower side's
/// resting so, the other as its wheels put it). `sides` gives the side of
/// each of the hull's `PARTS` (the layout's
/// [`part_sides`](crate::spatial::SpatialLayout::part_sides)). An invalid
/// terrain is an error of the right side, where the work starts.
#[allow(clippy::too_many_arguments)]
pub fn assemble_sides<H, const DH: usize, R, const DR: usize, L, const DL: usize>(
    hull: &H,
    (right, left): (&R, &L),
    sides: &[Side],
    shoe: &ShoeGeometry,
    profile: &ToothProfile,
    terrain: &Terrain,
    x: f64,
    clearance: f64,
) -> Result<AssembledSides<DH, DR, DL>, SideError>
where
    H: ChassisModel<DH>,
    R: TrackModel<DR>,
    L: TrackModel<DL>,
{
    assemble_on_grounds(
        hull,
        (right, left),
        sides,
        (shoe, profile),
        (terrain, terrain),
        x,
        clearance,
    )
}

/// [`assemble_sides`] with each track on its own ground (`grounds`:
/// under the right track, under the left): the hull lowered until the
/// first track comes within `clearance` (m) of its ground, the other
/// resting as its wheels put it. A ground that is invalid, or that a
/// track would start in, is an error of that track's side.
pub fn assemble_on_grounds<H, const DH: usize, R, const DR: usize, L, const DL: usize>(
    hull: &H,
    (right, left): (&R, &L),
    sides: &[Side],
    (shoe, profile): (&ShoeGeometry, &ToothProfile),
    (right_ground, left_ground): (&Terrain, &Terrain),
    x: f64,
    clearance: f64,
) -> Result<AssembledSides<DH, DR, DL>, SideError>
where
    H: ChassisModel<DH>,
    R: TrackModel<DR>,
    L: TrackModel<DL>,
{
    let on = |side: Side| move |error: AssemblyError| SideError { side, error };
    right_ground
        .check()
        .map_err(|e| on(Side::Right)(e.into()))?;
    left_ground.check().map_err(|e| on(Side::Left)(e.into()))?;
    let parts = |side: Side| -> Vec<ChassisPart> {
        H::PARTS
            .iter()
            .zip(sides)
            .filter(|(_, s)| **s == side)
            .map(|(p, _)| *p)
            .collect()
    };
    let (right_parts, left_parts) = (parts(Side::Right), parts(Side::Left));
    let mut qh = SVector::<f64, DH>::zeros();
    qh[0] = x;
    let mut r = Gear::tensioned(right, hull, &right_parts, &mut qh, shoe, profile)
        .map_err(on(Side::Right))?;
    let mut l =
        Gear::tensioned(left, hull, &left_parts, &mut qh, shoe, profile).map_err(on(Side::Left))?;
    let drop = r
        .drop(shoe, right_ground, clearance)
        .min(l.drop(shoe, left_ground, clearance));
    r.lower(&mut qh, drop);
    // Both sides share the hull: lower the left's circles alone.
    l.lower(&mut SVector::<f64, DH>::zeros(), drop);
    let qr = r.wrap(right, &mut qh, profile).map_err(on(Side::Right))?;
    let ql = l.wrap(left, &mut qh, profile).map_err(on(Side::Left))?;
    check_start(
        right,
        hull,
        &right_parts,
        (&qr, &qh),
        shoe,
        profile,
        right_ground,
    )
    .map_err(on(Side::Right))?;
    check_start(
        left,
        hull,
        &left_parts,
        (&ql, &qh),
        shoe,
        profile,
        left_ground,
    )
    .map_err(on(Side::Left))?;
    Ok(AssembledSides {
        hull: qh,
        right: qr,
        left: ql,
        tensioners: [r.tensioner, l.tensioner],
    })
}
