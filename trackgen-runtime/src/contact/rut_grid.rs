//! The plastic memory of the ground over an area, for tracks that steer:
//! a [`SoilMemory`] per square cell, interpolated bilinearly between the
//! cells' centres. The planar [`Rut`](super::soft_ground::Rut) remembers
//! along `x` alone; a vehicle in space leaves two ruts that may turn,
//! cross and be driven over again, so the memory is kept over `(x, y)`.
//!
//! Only the cells a shoe has pressed are kept, in square blocks of
//! 16 × 16 cells found by a hash of the block's index: memory grows with
//! the area pressed (the M113's two ruts some 60 kB per metre driven at
//! the default 2 cm cell: blocks at a footprint's edges are partly
//! empty), and a lookup is a hash and an index. Each block keeps when
//! it was first pressed (the grid's clock, [`RutGrid::at_time`]), so a
//! picture can draw the rut as it grew ([`RutGrid::patches`]).

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

use nalgebra::Vector2;

use crate::terrain::soil::{Soil, SoilMemory};

/// Cells along each side of a block.
const BLOCK: usize = 16;

/// A block's cells, row by row along `x`, and when it was first
/// pressed, s.
#[derive(Debug, Clone, PartialEq)]
struct Block {
    cells: [SoilMemory; BLOCK * BLOCK],
    since: f64,
}

/// The plastic memory of the ground over `(x, y)`: fresh soil where
/// nothing has pressed.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RutGrid {
    cell: f64,
    blocks: HashMap<(i64, i64), Box<Block>, BuildHasherDefault<CellHasher>>,
    /// The time a block pressed now is stamped with, s.
    now: f64,
}

/// A square of a rut for a picture ([`RutGrid::patches`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RutPatch {
    /// Its centre, m.
    pub centre: Vector2<f64>,
    /// Its side, m.
    pub side: f64,
    /// The mean plastic sinkage of its pressed cells, m.
    pub sinkage: f64,
    /// When the block holding it was first pressed, s.
    pub since: f64,
}

impl RutGrid {
    /// Fresh ground, remembered in square cells `cell` m on a side.
    pub fn new(cell: f64) -> RutGrid {
        RutGrid {
            cell,
            blocks: HashMap::default(),
            now: 0.0,
        }
    }

    /// Sets the grid's clock to `t` (s): a block first pressed from now
    /// on is stamped with it.
    pub fn at_time(&mut self, t: f64) {
        self.now = t;
    }

    /// The cell's side, m.
    pub fn cell(&self) -> f64 {
        self.cell
    }

    /// Cell `(i, j)`'s memory.
    fn at(&self, (i, j): (i64, i64)) -> SoilMemory {
        let (block, k) = split(i, j);
        self.blocks
            .get(&block)
            .map_or_else(SoilMemory::default, |b| b.cells[k])
    }

    /// Cell `(i, j)`, its block created fresh if nothing was pressed in it.
    fn at_mut(&mut self, (i, j): (i64, i64)) -> &mut SoilMemory {
        let (block, k) = split(i, j);
        let since = self.now;
        &mut self
            .blocks
            .entry(block)
            .or_insert_with(|| {
                Box::new(Block {
                    cells: [SoilMemory::default(); BLOCK * BLOCK],
                    since,
                })
            })
            .cells[k]
    }

    /// The rut in squares of `cells` × `cells` cells (1 to 16; a
    /// block's last squares smaller where `cells` does not divide 16), for
    /// a picture: every square holding a cell pressed below the surface
    /// (plastic sinkage above 0), its mean sinkage over those cells and
    /// its block's first pressing, in the blocks' order along `y` then
    /// `x` (the same list whatever the hash's order).
    pub fn patches(&self, cells: usize) -> Vec<RutPatch> {
        let n = cells.clamp(1, BLOCK);
        let mut keys: Vec<&(i64, i64)> = self.blocks.keys().collect();
        keys.sort_unstable_by_key(|&&(bi, bj)| (bj, bi));
        let mut out = Vec::new();
        for key in keys {
            let block = &self.blocks[key];
            for pj in (0..BLOCK).step_by(n) {
                for pi in (0..BLOCK).step_by(n) {
                    let (mut sum, mut count) = (0.0, 0usize);
                    let (ni, nj) = (n.min(BLOCK - pi), n.min(BLOCK - pj));
                    for j in pj..pj + nj {
                        for i in pi..pi + ni {
                            let plastic = block.cells[j * BLOCK + i].plastic;
                            if plastic > 0.0 {
                                sum += plastic;
                                count += 1;
                            }
                        }
                    }
                    if count == 0 {
                        continue;
                    }
                    let first = Vector2::new(
                        (key.0 * BLOCK as i64 + pi as i64) as f64,
                        (key.1 * BLOCK as i64 + pj as i64) as f64,
                    );
                    let middle = Vector2::new(0.5 * ni as f64, 0.5 * nj as f64);
                    out.push(RutPatch {
                        centre: (first + middle) * self.cell,
                        side: n as f64 * self.cell,
                        sinkage: sum / count as f64,
                        since: block.since,
                    });
                }
            }
        }
        out
    }

    /// The memory at `(x, y)`, m: bilinear between the four cell centres
    /// around it (along `x` alone, across a cell whose neighbours across
    /// remember the same, it is the planar rut's interpolation).
    pub fn memory(&self, at: Vector2<f64>) -> SoilMemory {
        let u = at / self.cell - Vector2::repeat(0.5);
        let (i, j) = (u.x.floor(), u.y.floor());
        let (wx, wy) = (u.x - i, u.y - j);
        let (i, j) = (i as i64, j as i64);
        let along = |j| {
            let (a, b) = (self.at((i, j)), self.at((i + 1, j)));
            [
                a.plastic + wx * (b.plastic - a.plastic),
                a.yield_pressure + wx * (b.yield_pressure - a.yield_pressure),
            ]
        };
        let (near, far) = (along(j), along(j + 1));
        SoilMemory {
            plastic: near[0] + wy * (far[0] - near[0]),
            yield_pressure: near[1] + wy * (far[1] - near[1]),
        }
    }

    /// Leaves `memory` in the cells whose centres lie under a patch centred
    /// at `centre` (m), `length` m along the unit direction `forward` and
    /// `width` m across it (at least the cell holding `centre`), where it
    /// is deeper than what they remember.
    pub fn imprint(
        &mut self,
        centre: Vector2<f64>,
        forward: Vector2<f64>,
        (length, width): (f64, f64),
        memory: SoilMemory,
        soil: &Soil,
    ) {
        let deepest = memory.deepest(soil);
        let press = |cell: &mut SoilMemory| {
            if deepest > cell.deepest(soil) {
                *cell = memory;
            }
        };
        let held = (
            (centre.x / self.cell).floor(),
            (centre.y / self.cell).floor(),
        );
        press(self.at_mut((held.0 as i64, held.1 as i64)));
        let (half_length, half_width) = (0.5 * length, 0.5 * width);
        let reach = Vector2::new(
            half_length * forward.x.abs() + half_width * forward.y.abs(),
            half_length * forward.y.abs() + half_width * forward.x.abs(),
        );
        let first = ((centre - reach) / self.cell).map(|u| (u - 0.5).ceil() as i64);
        let last = ((centre + reach) / self.cell).map(|u| (u - 0.5).floor() as i64);
        for i in first.x..=last.x {
            for j in first.y..=last.y {
                let offset = Vector2::new(i as f64 + 0.5, j as f64 + 0.5) * self.cell - centre;
                let along = offset.dot(&forward);
                let across = offset.perp(&forward);
                if along.abs() <= half_length && across.abs() <= half_width {
                    press(self.at_mut((i, j)));
                }
            }
        }
    }
}

/// Cell `(i, j)`'s block and its index in the block.
#[inline]
fn split(i: i64, j: i64) -> ((i64, i64), usize) {
    let size = BLOCK as i64;
    let (bi, bj) = (i.div_euclid(size), j.div_euclid(size));
    let k = (j.rem_euclid(size) * size + i.rem_euclid(size)) as usize;
    ((bi, bj), k)
}

/// A hash of a block's two indices: one multiply and rotate per index
/// (the rustc compiler's "Fx" mix), where the standard hasher's
/// resistance to chosen keys buys nothing.
#[derive(Default, Clone, Copy)]
struct CellHasher(u64);

impl Hasher for CellHasher {
    fn finish(&self) -> u64 {
        self.0
    }

    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }

    fn write_u64(&mut self, value: u64) {
        self.0 = (self.0.rotate_left(5) ^ value).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }

    fn write_i64(&mut self, value: i64) {
        self.write_u64(value as u64);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::terrain::soil::SoilPreset;

    fn pressed(plastic: f64) -> SoilMemory {
        SoilMemory {
            plastic,
            yield_pressure: 1e5,
        }
    }

    #[test]
    fn fresh_ground_remembers_nothing() {
        let rut = RutGrid::new(0.02);
        assert_eq!(rut.memory(Vector2::new(3.1, -7.2)), SoilMemory::default());
    }

    /// A patch across the axes: every cell centre under it takes its
    /// memory, none outside (checked cell by cell against the rectangle),
    /// and inside, away from its edges, the interpolated memory is the
    /// patch's exactly; across a negative index the blocks join.
    #[test]
    fn a_patch_is_imprinted_over_its_footprint() {
        let soil = SoilPreset::DrySand.soil();
        let mut rut = RutGrid::new(0.02);
        let centre = Vector2::new(-0.013, 0.507);
        let forward = Vector2::new(0.6, 0.8);
        let memory = pressed(0.05);
        rut.imprint(centre, forward, (0.2, 0.1), memory, &soil);
        for i in -20..20 {
            for j in 10..40 {
                let c = Vector2::new(i as f64 + 0.5, j as f64 + 0.5) * 0.02;
                let d = c - centre;
                let inside = d.dot(&forward).abs() <= 0.1 && d.perp(&forward).abs() <= 0.05;
                assert_eq!(rut.at((i, j)) == memory, inside, "cell ({i}, {j})");
            }
        }
        assert_eq!(rut.memory(centre), memory);
        // A shallower memory does not replace a deeper one.
        rut.imprint(centre, forward, (0.2, 0.1), pressed(0.01), &soil);
        assert_eq!(rut.memory(centre), memory);
    }

    /// The patches for a picture: a footprint 0.2 × 0.1 m at the origin
    /// (cells of 2 cm: 10 × 5 of them, across four blocks) pressed 5 cm at
    /// 1.5 s, then one a block away at 2.0 s. In squares of 4 cells every
    /// pressed cell falls in one square, the squares' mean sinkage is the
    /// footprint's, and each keeps its block's first time, also where a
    /// block is pressed again later.
    #[test]
    fn the_patches_draw_the_rut_as_it_grew() {
        let soil = SoilPreset::DrySand.soil();
        let mut rut = RutGrid::new(0.02);
        rut.at_time(1.5);
        rut.imprint(
            Vector2::zeros(),
            Vector2::x(),
            (0.2, 0.1),
            pressed(0.05),
            &soil,
        );
        rut.at_time(2.0);
        rut.imprint(
            Vector2::new(0.0, 0.001),
            Vector2::x(),
            (0.2, 0.1),
            pressed(0.05),
            &soil,
        );
        rut.imprint(
            Vector2::new(1.0, 0.04),
            Vector2::x(),
            (0.04, 0.04),
            pressed(0.03),
            &soil,
        );
        let patches = rut.patches(4);
        let early: Vec<_> = patches.iter().filter(|p| p.since == 1.5).collect();
        let late: Vec<_> = patches.iter().filter(|p| p.since == 2.0).collect();
        assert_eq!(early.len() + late.len(), patches.len());
        for p in &early {
            assert!(p.centre.norm() < 0.2, "{p:?}");
            // The mean of up to 16 equal sinkages, to its rounding.
            assert_eq!(p.side, 0.08);
            assert!((p.sinkage - 0.05).abs() < 1e-15, "{p:?}");
        }
        // 10 × 5 cells under the first footprint: columns −5…4 fall in
        // squares −8…−5, −4…−1, 0…3, 4…7; rows −3…2 (the second
        // footprint's 1 mm shift adds row 2) in −4…−1 and 0…3.
        assert_eq!(early.len(), 4 * 2);
        assert_eq!(late.len(), 1);
        assert!((late[0].sinkage - 0.03).abs() < 1e-15, "{:?}", late[0]);
        // Cells 49 and 50 along, 1 and 2 across: the square of cells
        // 48…51 and 0…3, centred at (50, 2) cells.
        assert!((late[0].centre - Vector2::new(1.0, 0.04)).norm() < 1e-15);
        // The same list whatever the hash's order: sorted by block.
        assert_eq!(rut.clone().patches(4), patches);
    }

    /// Between two cell centres along `x`, with the same memory across,
    /// the memory is linear, as the planar rut's.
    #[test]
    fn between_cells_the_memory_is_linear() {
        let soil = SoilPreset::DrySand.soil();
        let mut rut = RutGrid::new(0.02);
        let forward = Vector2::x();
        rut.imprint(
            Vector2::new(0.01, 0.01),
            forward,
            (0.0, 0.1),
            pressed(0.04),
            &soil,
        );
        let at = rut.memory(Vector2::new(0.015, 0.01));
        assert!((at.plastic - 0.75 * 0.04).abs() < 1e-15, "{at:?}");
    }
}
