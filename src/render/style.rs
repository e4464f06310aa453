//! Colours and line styles. The kinds use the Okabe–Ito palette (safe for
//! the common colour-vision deficiencies); overlays differ by colour *and*
//! by line style and hatch direction, so they stay apart in grey too.

use super::drawing::{Hatch, Rgba, Stroke};
use crate::model::{ConnectionKind, SpaceKind};

/// Okabe–Ito colours.
pub mod okabe_ito {
    use super::Rgba;
    /// Black.
    pub const BLACK: Rgba = Rgba::rgb(0, 0, 0);
    /// Orange.
    pub const ORANGE: Rgba = Rgba::rgb(230, 159, 0);
    /// Sky blue.
    pub const SKY_BLUE: Rgba = Rgba::rgb(86, 180, 233);
    /// Bluish green.
    pub const BLUISH_GREEN: Rgba = Rgba::rgb(0, 158, 115);
    /// Yellow.
    pub const YELLOW: Rgba = Rgba::rgb(240, 228, 66);
    /// Blue.
    pub const BLUE: Rgba = Rgba::rgb(0, 114, 178);
    /// Vermillion.
    pub const VERMILLION: Rgba = Rgba::rgb(213, 94, 0);
    /// Reddish purple.
    pub const REDDISH_PURPLE: Rgba = Rgba::rgb(204, 121, 167);
}

use okabe_ito::*;

/// Fill of a space by kind: room sky blue, corridor orange, door bluish
/// green, stairs reddish purple, elevator blue, other yellow
/// (semi-transparent so the map shows through).
pub fn kind_fill(kind: SpaceKind) -> Rgba {
    match kind {
        SpaceKind::Room => SKY_BLUE,
        SpaceKind::Corridor => ORANGE,
        SpaceKind::Door => BLUISH_GREEN,
        SpaceKind::Stairs => REDDISH_PURPLE,
        SpaceKind::Elevator => BLUE,
        SpaceKind::Other => YELLOW,
    }
    .with_alpha(170)
}

/// Outline of every space.
pub fn space_outline() -> Stroke {
    Stroke::solid(Rgba::rgb(60, 60, 60), 1.0)
}

/// A door's doorway line (its opening, jamb to jamb): dark bluish green.
pub fn doorway_stroke() -> Stroke {
    Stroke::solid(Rgba::rgb(0, 90, 66), 2.0)
}

/// An edge of the graph by connection kind: door solid black, open long
/// dashes, adjacent thin grey dots, vertical reddish purple dots.
pub fn edge_stroke(kind: ConnectionKind) -> Stroke {
    match kind {
        ConnectionKind::Door => Stroke::solid(BLACK, 1.5),
        ConnectionKind::Open => Stroke::dashed(BLACK, 1.5, &[6.0, 3.0]),
        ConnectionKind::Adjacent => Stroke::dashed(Rgba::rgb(110, 110, 110), 1.0, &[1.5, 3.0]),
        ConnectionKind::Vertical => Stroke::dashed(REDDISH_PURPLE, 2.0, &[2.0, 2.0]),
    }
}

/// The route line: thick vermillion.
pub fn route_stroke() -> Stroke {
    Stroke::solid(VERMILLION.with_alpha(230), 5.0)
}

/// The kinds of change drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Change {
    /// Only in the new revision.
    Added,
    /// Only in the old revision.
    Removed,
    /// In both, different.
    Changed,
    /// A part of a split space.
    Split,
    /// The result of a merge.
    Merged,
}

impl Change {
    /// Name used in classes and the legend.
    pub fn as_str(self) -> &'static str {
        match self {
            Change::Added => "added",
            Change::Removed => "removed",
            Change::Changed => "changed",
            Change::Split => "split",
            Change::Merged => "merged",
        }
    }

    /// Outline: added blue solid, removed black dashed, changed reddish
    /// purple dotted, split vermillion dash-dot, merged black long dashes.
    pub fn stroke(self) -> Stroke {
        match self {
            Change::Added => Stroke::solid(BLUE, 3.0),
            Change::Removed => Stroke::dashed(BLACK, 3.0, &[7.0, 4.0]),
            Change::Changed => Stroke::dashed(REDDISH_PURPLE, 3.0, &[2.0, 3.0]),
            Change::Split => Stroke::dashed(VERMILLION, 3.0, &[8.0, 3.0, 2.0, 3.0]),
            Change::Merged => Stroke::dashed(BLACK, 3.0, &[12.0, 4.0]),
        }
    }

    /// Hatching: added "/", removed "\", changed vertical, split
    /// horizontal, merged steep "/".
    pub fn hatch(self) -> Hatch {
        let (colour, angle_deg) = match self {
            Change::Added => (BLUE, 45.0),
            Change::Removed => (BLACK, 135.0),
            Change::Changed => (REDDISH_PURPLE, 90.0),
            Change::Split => (VERMILLION, 0.0),
            Change::Merged => (BLACK, 67.5),
        };
        Hatch {
            colour: colour.with_alpha(200),
            spacing: 7.0,
            angle_deg,
            width: 1.5,
        }
    }
}

/// The map's cells: free white, occupied dark grey, unknown light grey.
pub fn map_grey(cell: crate::grid::Cell) -> u8 {
    match cell {
        crate::grid::Cell::Free => 255,
        crate::grid::Cell::Occupied => 40,
        crate::grid::Cell::Unknown => 215,
    }
}
