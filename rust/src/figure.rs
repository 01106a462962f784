//! The picture of one decision, as the papers draw it: what a viewer needs
//! to draw why a step went where it did, placed on the grid here, once.
//! The page's 2D figure and its 3D overlay draw from the same value (see
//! `step_detail`), so neither works geometry out of decision columns.
//!
//! A decision type says which picture its steps have ([`Decision::FIGURE`])
//! and makes it ([`Decision::figure`]); the geometry of a paper's figure
//! lives beside the algorithm it belongs to (Wang's Fig. 4b in
//! `line::regions_wang`, Saleem's candidates in `arc::circle_saleem`).
//!
//! [`Decision::FIGURE`]: crate::trace::Decision::FIGURE
//! [`Decision::figure`]: crate::trace::Decision::figure

use serde::Serialize;
use tsify::Tsify;

/// Which picture a decision has: the `kind` of its [`DecisionFigure`].
#[derive(Serialize, Tsify, Clone, Copy, Debug, PartialEq, Eq)]
#[serde(rename_all = "camelCase")]
pub enum FigureKind {
    ExitFace,
    ErrorTerms,
    ArcCandidates,
}

/// The picture of one step's decision.
#[derive(Serialize, Tsify, Clone, Debug, PartialEq)]
#[serde(tag = "kind", rename_all = "camelCase")]
pub enum DecisionFigure {
    /// Wang's discriminate regions: the exit face the ideal line crosses.
    ExitFace(ExitFace),
    /// Bresenham: each error term against the threshold it is compared with.
    ErrorTerms(ErrorTerms),
    /// Saleem's circle: the two candidate cells and their residuals.
    ArcCandidates(ArcCandidates),
}

impl DecisionFigure {
    pub fn kind(&self) -> FigureKind {
        match self {
            DecisionFigure::ExitFace(_) => FigureKind::ExitFace,
            DecisionFigure::ErrorTerms(_) => FigureKind::ErrorTerms,
            DecisionFigure::ArcCandidates(_) => FigureKind::ArcCandidates,
        }
    }
}

/// A grid axis and a way along it.
#[derive(Serialize, Tsify, Clone, Copy, Debug, PartialEq, Eq)]
pub struct SignedAxis {
    /// 0 = x, 1 = y, 2 = z.
    pub axis: u8,
    /// +1 or -1.
    pub sign: i8,
}

impl SignedAxis {
    /// The axis of a `grid::SIGNED_AXIS_LABELS` index (see `grid::signed_axis`).
    pub fn of_label_index(index: u8) -> SignedAxis {
        SignedAxis {
            axis: index / 2,
            sign: if index % 2 == 0 { 1 } else { -1 },
        }
    }
}

/// The exit face of one step of Wang's method of discriminate regions (Wang
/// Fig. 4): the unit cell the step crosses, the face of it where the active
/// axes arrive, split into the regions a-d by the segments e-h that meet at
/// its center o, where the ideal line crosses that face's plane, and the
/// corner A-D the step goes to.
///
/// Face coordinates are cells from the face's center: u along the first
/// passive axis, v along the second, each positive the way its axis
/// travels. Wang's Fig. 4b in them: B is the corner where neither passive
/// axis steps (-1/2, -1/2), A where the first does (1/2, -1/2), C the
/// second (-1/2, 1/2), D both (1/2, 1/2). With one passive axis (Wang's
/// line types ⑤-⑦) the active axes arrive together, so the line leaves
/// through an edge, not a face: the edge B-A, at v = -1/2 (a missing N
/// counts as negative), with only the parts on it (regions a and b, the
/// point e between them, corners A and B).
#[derive(Serialize, Tsify, Clone, Debug, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct ExitFace {
    /// The region a-d, segment e-h or center o the ideal line crosses.
    pub region: &'static str,
    /// The corner A-D the step goes to (the point it reached).
    pub corner: &'static str,
    /// The grid axis and direction of u: the first passive axis.
    pub u_axis: SignedAxis,
    /// The grid axis and direction of v: the second passive axis; null
    /// with one passive axis (the face is then the edge B-A).
    pub v_axis: Option<SignedAxis>,
    /// Where the ideal line crosses the exit plane, face coordinates
    /// (u = M / 2|Δx|, v = N / 2|Δx|, Wang eq. 3-6; v = -1/2 on an edge).
    /// It lies within (-1, 1) of the center: past 1/2 the line left Wang's
    /// unit cell through a side first, in the same quadrant, so the regions
    /// are drawn on past the face as quadrants of its plane.
    pub crossing: [f64; 2],
    /// The regions the face has, each the quadrant of the exit plane whose
    /// (u, v) have the signs given.
    pub regions: Vec<FaceRegion>,
    /// The segments between regions and the center o, face coordinates; a
    /// part whose ends are the same point is that point (o, or e on an edge).
    pub segments: Vec<FaceSegment>,
    /// The corners the face has, face coordinates.
    pub corners: Vec<FaceCorner>,
    /// The face's center, grid coordinates: half a cell past the point
    /// before the step along each passive axis, where the step arrived along
    /// each active one.
    pub center: Vec<f64>,
    /// The unit cell the step crosses, as two opposite grid points: the
    /// point before the step, and one cell from it along every axis the
    /// way that axis travels.
    pub cell: [Vec<i64>; 2],
}

#[derive(Serialize, Tsify, Clone, Debug, PartialEq)]
pub struct FaceRegion {
    pub name: &'static str,
    /// Signs of u and v in the region's quadrant (each +1 or -1).
    pub quadrant: [i8; 2],
}

#[derive(Serialize, Tsify, Clone, Debug, PartialEq)]
pub struct FaceSegment {
    pub name: &'static str,
    pub from: [f64; 2],
    pub to: [f64; 2],
}

#[derive(Serialize, Tsify, Clone, Debug, PartialEq)]
pub struct FaceCorner {
    pub name: &'static str,
    pub at: [f64; 2],
}

/// Bresenham's decision: each minor axis's error term against the
/// threshold it is compared with.
#[derive(Serialize, Tsify, Clone, Debug, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct ErrorTerms {
    pub terms: Vec<ErrorTerm>,
    pub threshold: i64,
}

#[derive(Serialize, Tsify, Clone, Debug, PartialEq)]
pub struct ErrorTerm {
    /// The decision column that holds the term.
    pub name: &'static str,
    pub value: i64,
    /// Its axis stepped (above the threshold, or on it as the tie policy said).
    pub steps: bool,
}

/// The two cells one step of Saleem's circle chose between (section 4,
/// eq. 6-7): they differ only along the slow axis, and the step takes the
/// one whose residual u² + v² - r² is nearer 0.
#[derive(Serialize, Tsify, Clone, Debug, PartialEq)]
pub struct ArcCandidates {
    /// The stay candidate (only the fast axis steps), then the move
    /// candidate (the slow axis steps too).
    pub candidates: [ArcCandidate; 2],
}

#[derive(Serialize, Tsify, Clone, Debug, PartialEq)]
pub struct ArcCandidate {
    /// "stay" or "move".
    pub name: &'static str,
    /// Grid coordinates; in a helix, at the height of the point the step
    /// reached (the residual does not depend on it).
    pub cell: Vec<i64>,
    pub residual: i64,
    /// The step went here: this cell is the point it reached.
    pub taken: bool,
}
