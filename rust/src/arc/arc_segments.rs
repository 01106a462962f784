//! Arcs split into chords, each chord stepped by a line algorithm: the
//! G-code interpreter blog's method ("How to Improve the 2-axis CNC GCODE
//! Interpreter to Understand Arcs"), with Grbl's chord-tolerance rule as
//! the alternative way to count chords.
//!
//! Chord count n (at least 1):
//! - `segmentLength` L (the blog's CM_PER_SEGMENT): n = floor(|sweep| r / L);
//! - `tolerance` t (Grbl's arc_tolerance, motion_control.c):
//!   n = floor(|sweep| r / (2 sqrt(t (2r - t)))): a chord of half-angle α has
//!   sagitta r (1 - cos α) = t when its half-length r sin α = sqrt(t (2r - t)),
//!   and Grbl counts arc length per chord as the chord length.
//!
//! Vertices: the arc point at fraction i / n of the sweep (i = 1..n-1), each
//! coordinate rounded to the nearest grid unit (halves away from zero), then
//! the exact end point: n chords, the last ending exactly on `to`. A vertex
//! that rounds onto the previous one is dropped (its chord would have no
//! steps). Each chord is the very trace `lineAlgorithm` gives for it.
//!
//! Deviation bound: a chord of the true arc is within its sagitta
//! s = r (1 - cos(|sweep| / 2n)) of the circle; rounding moves each vertex at
//! most sqrt(2)/2 (sqrt(3)/2 for a helix, whose height is rounded too); the
//! line algorithm stays within its own bound of the rounded chord (sqrt(2)/2
//! for regions). So every point is within s + sqrt(2)/2 + sqrt(2)/2 of the arc.

use super::angle::{degrees, sin_cos_turns};
use super::{ArcSpec, CENTER, DIR, PLANE, TURNS};
use crate::algorithm_info::{AlgorithmInfo, Example, Family, Find};
use crate::error::{Error, TooManyChords, counted, number_text};
use crate::grid::{Point, round_half_away_within, round_ratio_half_away};
use crate::ideal::IdealPath;
use crate::ideal::curve::HelixPath;
use crate::line::line_stepper::{IntoSink, LineStepper, MakeSegment, StepperVisitor};
use crate::line::regions_wang::RegionsWhy;
use crate::plan::Plan;
use crate::range::NumberRange;
use crate::request::{FROM, MAX_STEPS, OptionKind, OptionSpec, Request, TO};
use crate::trace::{Decision, MadeSegment, Stepper, Trace, TraceBuilder, path_too_long};
use serde_json::{Map, Value};
use std::rc::Rc;

pub const ID: &str = "arc-segments";

/// Catalogue ids a chord may be stepped with: the algorithms that take 3
/// axes and need no option but from and to (a test checks the catalogue
/// against this list, so a new line algorithm is not silently left out).
pub const LINE_ALGORITHMS: &[&str] = &[
    "regions",
    "bresenham3d",
    "nd",
    "liu-float",
    "greedy",
    "walk6",
    "dda",
];

/// Most chords one arc may be split into: each chord is a trace segment
/// with its own replay state and note.
pub const MAX_CHORDS: u64 = 1 << 16;

/// Fewest chords of a full circle: a triangle around the center.
pub const MIN_FULL_CIRCLE_CHORDS: u64 = 3;

pub const SEGMENT_LENGTH: OptionSpec = OptionSpec {
    name: "segmentLength",
    kind: OptionKind::Number(NumberRange::positive("grid units")),
    required: false,
    default: None,
    applies_with: None,
    doc: "Chord length, grid units: chords = floor(arc length / segmentLength), the blog's CM_PER_SEGMENT rule. Give this or tolerance.",
};

pub const TOLERANCE: OptionSpec = OptionSpec {
    name: "tolerance",
    // Less than the arc's diameter too, which only the arc knows (Chording::chords).
    kind: OptionKind::Number(NumberRange::positive("grid units")),
    required: false,
    default: Some("0.5"),
    applies_with: None,
    doc: "Chord sagitta aimed at, grid units (Grbl's arc_tolerance): chords = floor(|sweep| r / (2 sqrt(tolerance (2r - tolerance)))). Used when segmentLength is not given.",
};

pub const LINE_ALGORITHM: OptionSpec = OptionSpec {
    name: "lineAlgorithm",
    kind: OptionKind::Choice {
        values: LINE_ALGORITHMS,
    },
    required: false,
    default: Some("regions"),
    applies_with: None,
    doc: "The line algorithm that steps each chord (a catalogue id).",
};

pub const LINE_TIE: OptionSpec = OptionSpec {
    name: "tie",
    kind: OptionKind::Choice {
        values: &["advance", "hold"],
    },
    required: false,
    default: None,
    applies_with: None,
    doc: "Tie rule passed to the line algorithm of the chords; by default that algorithm's own.",
};

pub const INFO: AlgorithmInfo = AlgorithmInfo {
    id: ID,
    example: Example {
        options: r#"{"from": [20, 0, 0], "to": [-20, 0, 0], "center": [0, 0, 0], "dir": "ccw", "plane": "xy", "segmentLength": 8}"#,
        why: "A half circle of radius 20 in chords of 8 units (the blog's CM_PER_SEGMENT rule).",
    },
    family: Family::Arc,
    title: "Arc as chords (G02/G03 split into lines)",
    citation: "\"How to Improve the 2-axis CNC GCODE Interpreter to Understand Arcs\" (Makelangelo / GcodeCNCdemo blog), sections Arc length with atan3() to Implementation; chord count by tolerance from Grbl's mc_arc (motion_control.c)",
    teaching: "Instead of stepping the circle itself, cut the arc into short straight chords and draw each with a line algorithm. Find the start and end angles with atan3 (atan2 moved into [0, 2π)), their difference is the sweep, fixed up by ±2π so it turns the right way; arc length = |sweep| × r. The blog takes floor(length / segment length) chords; Grbl instead takes as many as keep each chord's sagitta near a tolerance t: floor(|sweep| r / (2 sqrt(t (2r - t)))). Because both round the count down, chords come out a little longer than asked: with floor, a chord's sagitta can reach (1 + 1/n)² times the tolerance (4 times when the count is rounded from just under 2 down to 1). Each vertex is the arc point at i/n of the sweep with each coordinate rounded to the nearest grid unit (halves away from zero); the last chord goes to the exact end point.",
    errata: &[
        "The post's Implementation fixes the sweep with `if(dir>0 && sweep<0) angle2+=2*PI; else if(dir<0) angle1+=2*PI;`: for dir < 0 it adds 2π even when the sweep is already negative, turning a quarter arc into 450°. The earlier snippet in the same post (`else if(dir==ARC_CCW && sweep>0)`) is right, and voxpath uses that rule (a reader's comment below the post asks about exactly this line).",
        "The post gives ARC_CW an increasing angle (positive sweep), which is clockwise only with the y axis pointing down, as on a screen. voxpath follows G-code's right-handed convention: G02 (cw) decreases the angle atan2(v, u) seen from the positive end of the plane's normal axis, G03 (ccw) increases it, in G17, G18 and G19 alike.",
        "With start = end the post's sweep is 0, and for dir > 0 no arc is drawn (for dir < 0 its fix of the first erratum adds 2π, a full circle by that same bug); in G-code that is a full circle in either direction, as in voxpath. The post also assumes arcs of at most 180°, equal start and end radius and constant Z; voxpath takes any sweep and extra turns, checks the radii, and steps helices with the helix algorithm (method segments is this post's chords, the height interpolated by angle).",
        "The loop `for(i=0;i<num_segments;++i)` first draws a line from the start to fraction 0, the start itself; voxpath starts at i = 1, giving the same path without the empty line.",
    ],
    // A trace has the columns of the chosen line algorithm; the catalogue
    // lists those of the default one.
    columns: RegionsWhy::COLUMNS,
    options: &[
        FROM,
        TO,
        CENTER,
        DIR,
        PLANE,
        TURNS,
        SEGMENT_LENGTH,
        TOLERANCE,
        LINE_ALGORITHM,
        LINE_TIE,
        MAX_STEPS,
    ],
    min_dims: 3,
    max_dims: 3,
    default_tie: None,
    compared_by: None,
    trace: |req, find| {
        let spec = ArcSpec::of_request(req, &INFO, false)?;
        trace_chords(ID, req, &spec, false, find)
    },
    plan: Some(|req, find| {
        let spec = ArcSpec::of_request(req, &INFO, false)?;
        plan_chords(req, &spec, false, find)
    }),
};

/// How many chords: the blog's fixed length or Grbl's tolerance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Chording {
    Length(f64),
    Tolerance(f64),
}

impl Chording {
    pub fn parse(req: &Request) -> Result<Chording, Error> {
        let length = req.declared_number(&SEGMENT_LENGTH)?;
        let tolerance = req.declared_number(&TOLERANCE)?;
        match (length, tolerance) {
            (Some(_), Some(_)) => Err(Error::field(
                "tolerance",
                "give segmentLength or tolerance, not both",
            )),
            (Some(l), None) => Ok(Chording::Length(l)),
            (None, t) => Ok(Chording::Tolerance(t.unwrap_or(0.5))),
        }
    }

    /// The option this count comes from.
    fn option(self) -> &'static str {
        match self {
            Chording::Length(_) => SEGMENT_LENGTH.name,
            Chording::Tolerance(_) => TOLERANCE.name,
        }
    }

    /// Number of chords (at least 1) for an arc of radius `r` sweeping
    /// `sweep_rad` (either sign). More than [`MAX_CHORDS`] is refused with
    /// the error's `too_many_chords` set, for a caller to word its own way.
    pub fn chords(self, r: f64, sweep_rad: f64) -> Result<u64, Error> {
        let arc_length = sweep_rad.abs() * r;
        let n = match self {
            // The blog: num_segments = floor(len / CM_PER_SEGMENT).
            Chording::Length(l) => (arc_length / l).floor(),
            Chording::Tolerance(t) => {
                if t >= 2.0 * r {
                    return Err(Error::field(
                        "tolerance",
                        format!(
                            "must be less than the diameter {:.3}, got {}",
                            2.0 * r,
                            number_text(t)
                        ),
                    ));
                }
                // Grbl: segments = floor(|0.5 * angular_travel * radius| /
                // sqrt(arc_tolerance * (2 * radius - arc_tolerance))).
                (0.5 * arc_length / (t * (2.0 * r - t)).sqrt()).floor()
            }
        };
        if n > MAX_CHORDS as f64 {
            return Err(TooManyChords {
                chords: n,
                most: MAX_CHORDS,
            }
            .error(self.option()));
        }
        Ok((n as u64).max(1))
    }

    fn describe(self, n: u64) -> String {
        match self {
            Chording::Length(l) => format!(
                "floor(arc length / segmentLength {l}) gives {}",
                counted(n, "chord")
            ),
            Chording::Tolerance(t) => format!(
                "Grbl's rule with tolerance {t} gives {}",
                counted(n, "chord")
            ),
        }
    }
}

/// A chord's end: its grid point and its fraction of the sweep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vertex {
    pub point: Point,
    pub fraction: f64,
}

/// How many units in the last place of |center| + r·(1 + |θ|) an in-plane
/// vertex coordinate may be from its exact value: the angle θ = start +
/// sweep·t is off by a few units of its own last place, which the sine
/// and cosine carry (times r) into the point, and they are within about
/// one of 1, their product with r and the sum with the center one each. A
/// coordinate that close below a half is that half. Without θ's share, an
/// arc of many turns rounded the same angle's halves one way on its first
/// turn and the other way on later ones (a circle of r = 3 at 30° a chord:
/// 32 of 264 coordinates at 10 turns, 337 of 2,424 at 100).
const VERTEX_HALF_ULPS: f64 = 8.0;

/// The chord ends after the start: arc points at fractions i / n rounded to
/// the grid, then the end point; a vertex equal to the one before is dropped.
/// For a helix (`spec.rise` != 0) the height is interpolated by the same
/// fraction and rounded too. Halves go away from zero, as everywhere: a
/// height exactly (rise·i/n in integers), an in-plane coordinate when
/// within its rounding error of a half (3 + 3 sin 30° came out
/// 1.4999999999999998 and went down, where 3 sin 210° went away from zero).
pub fn vertices(spec: &ArcSpec, n: u64) -> Vec<Vertex> {
    let [u, v, normal] = spec.plane.axes();
    let c = &spec.frame.center;
    let (r, start, sweep) = (spec.radius(), spec.start_rad(), spec.sweep_rad());
    let error = |center: i64, theta: f64| {
        (center.unsigned_abs() as f64 + r * (1.0 + theta.abs())) * (VERTEX_HALF_ULPS * f64::EPSILON)
    };
    let mut out: Vec<Vertex> = Vec::with_capacity(n as usize);
    // Compared as three coordinates, not as Points: a Point is MAX_AXES
    // coordinates and its axis count, and comparing two was a memcmp call.
    let to = spec.to.coords();
    let mut previous = [spec.from.get(0), spec.from.get(1), spec.from.get(2)];
    for i in 1..=n {
        let p = if i == n {
            [to[0], to[1], to[2]]
        } else {
            let t = i as f64 / n as f64;
            let theta = start + sweep * t;
            let mut p = [0; 3];
            let (sin, cos) = sin_cos_turns(theta);
            p[u] = round_half_away_within(c.get(u) as f64 + r * cos, error(c.get(u), theta)) as i64;
            p[v] = round_half_away_within(c.get(v) as f64 + r * sin, error(c.get(v), theta)) as i64;
            p[normal] =
                spec.from.get(normal) + round_ratio_half_away(spec.rise * i as i64, n as i64);
            p
        };
        if p != previous {
            out.push(Vertex {
                point: Point::new(&p),
                fraction: i as f64 / n as f64,
            });
            previous = p;
        }
    }
    out
}

/// Traces the arc (or helix) of `spec` as chords stepped by the request's
/// line algorithm, which `find` looks up in the catalogue. `helical`:
/// measure against the helix rather than the arc.
pub fn trace_chords(
    id: &str,
    req: &Request,
    spec: &ArcSpec,
    helical: bool,
    find: Find,
) -> Result<Trace, Error> {
    chords_by(id, req, spec, helical, find, true)
}

/// An arc's chords ready to run: their vertices and notes, their line
/// algorithm and its stepper, and the fewest steps they take.
struct Chorded {
    notes: Rc<ChordNotes>,
    chords: Rc<Chords>,
    line_request: Request,
    line_info: &'static AlgorithmInfo,
    /// The sum of the chords' largest |Δ|.
    at_least: u64,
}

/// The chords of the arc of `spec` by the request's line algorithm (see
/// [`chords_by`]), refused when they would take more than maxSteps.
fn chorded(
    req: &Request,
    spec: &ArcSpec,
    helical: bool,
    find: Find,
    in_place: bool,
) -> Result<Chorded, Error> {
    let chording = Chording::parse(req)?;
    let line = req.choice(&LINE_ALGORITHM)?.unwrap_or(LINE_ALGORITHMS[0]);
    let line_info = find(line)?;
    let tie = req.choice(&LINE_TIE)?;
    // A tie for a line algorithm without a tie rule would be dropped, and
    // the chords stepped as without it.
    let takes_tie = |info: &AlgorithmInfo| info.options.iter().any(|o| o.name == LINE_TIE.name);
    if tie.is_some() && !takes_tie(line_info) {
        let with_ties: Vec<&str> = LINE_ALGORITHMS
            .iter()
            .copied()
            .filter(|&id| find(id).is_ok_and(takes_tie))
            .collect();
        return Err(Error::field(
            LINE_TIE.name,
            format!(
                "{line}, the chords' lineAlgorithm, has no tie rule to pass it to; tie is for {}",
                with_ties.join(", ")
            ),
        ));
    }
    let counted = chording.chords(spec.radius(), spec.sweep_rad())?;
    // A full circle (ending where it starts, at its own height) in fewer
    // than 3 chords would be one chord from the start to itself, or two out
    // and back: no steps, or no circle. It takes at least 3, the fewest
    // that go around the center (the blog and Grbl would not move at all).
    let closed = spec.from == spec.to && spec.rise == 0;
    let n = if closed {
        counted.max(MIN_FULL_CIRCLE_CHORDS)
    } else {
        counted
    };
    let chords = vertices(spec, n);
    let arc = spec.ideal_arc();
    let helix = HelixPath::new(arc.clone(), 0.0, spec.rise as f64);
    let max_steps = req.max_steps()?;
    // A line algorithm moves each axis at most one unit per step, so a
    // chord takes at least its largest |Δ| steps: an arc that needs more
    // than maxSteps by that count alone is refused before any chord runs.
    // Read in place: a Mirror made per chord for its longest |Δ| (points
    // copied into it) took about 5% of the r = 300,000 circle's 1,720
    // chords in wasm.
    let ends = std::iter::once(&spec.from).chain(chords.iter().map(|v| &v.point));
    let at_least: u64 = ends
        .zip(chords.iter())
        .map(|(a, b)| a.chebyshev_to(&b.point))
        .sum();
    if at_least > max_steps {
        return Err(path_too_long(max_steps, at_least));
    }
    let mut line_options = Map::new();
    if let Some(tie) = tie {
        line_options.insert("tie".into(), Value::from(tie));
    }
    let line_request = Request::new(line, line_options);
    let notes = Rc::new(ChordNotes {
        spec: spec.clone(),
        chording,
        counted,
        taken: n,
        chords,
        line: line_info.id,
    });
    let stepper = if in_place {
        LineStepper::for_request(line_info, &line_request)
    } else {
        LineStepper::ByRequest
    };
    let chords = Rc::new(Chords {
        notes: Rc::clone(&notes),
        stepper,
        helix,
        helical,
    });
    Ok(Chorded {
        notes,
        chords,
        line_request,
        line_info,
        at_least,
    })
}

/// The chords of the arc of `spec` planned ([`crate::plan`]), where
/// their line algorithm has a [`LineStepper`]: their steps are each
/// chord's stepper's count, and they end at the last vertex.
pub fn plan_chords(
    req: &Request,
    spec: &ArcSpec,
    helical: bool,
    find: Find,
) -> Result<Option<Plan>, Error> {
    let Chorded { notes, chords, .. } = chorded(req, spec, helical, find, true)?;
    let mut steps = 0;
    for k in 0..notes.chords.len() {
        let (from, to) = notes.ends(k);
        match chords.stepper.steps_between(from.point, to.point) {
            Some(n) => steps += n,
            None => return Ok(None),
        }
    }
    if steps > req.max_steps()? {
        return Ok(None);
    }
    Ok(Some(Plan {
        start: spec.from,
        end: notes.chords.last().map_or(spec.from, |v| v.point),
        steps,
        run_into: Box::new(move |sink| {
            for k in 0..chords.notes.chords.len() {
                let (from, to) = chords.notes.ends(k);
                debug_assert_eq!(
                    sink.position(),
                    from.point,
                    "a chord starts where the last ended"
                );
                chords
                    .stepper
                    .with_stepper(from.point, to.point, IntoSink(sink));
            }
        }),
    }))
}

/// [`trace_chords`], its chords' steppers run straight into the arc's
/// trace when `in_place` and the line algorithm has a [`LineStepper`],
/// else each chord the catalogue's trace, appended (the tests hold the
/// two to the same trace).
fn chords_by(
    id: &str,
    req: &Request,
    spec: &ArcSpec,
    helical: bool,
    find: Find,
    in_place: bool,
) -> Result<Trace, Error> {
    let Chorded {
        notes,
        chords,
        line_request,
        line_info,
        at_least,
    } = chorded(req, spec, helical, find, in_place)?;
    let mut builder = TraceBuilder::for_request(spec.from, req)?;
    let stepper = chords.stepper;
    if let LineStepper::ByRequest = stepper {
        by_requests(
            &mut builder,
            &notes,
            &line_request,
            line_info,
            find,
            |from, to| chords.ideal_between(from, to),
        )?;
        // A segment per chord, in order: each note made when read (most
        // are not), the chord's sentence before its stepper's.
        return Ok(builder
            .finish(id)
            .with_note_prefix(Rc::new(move |k| notes.prefix(k))));
    }
    // Each chord's stepper straight into the arc's trace, measured against
    // its piece of the arc; a chord shorter than a checkpoint interval (all
    // but the longest) is made again when read, from its ends, as a G-code
    // program's moves are: an arc of many chords keeps no stepper, ideal
    // path or segment record per chord (the circle of r = 300,000 in 1,720
    // chords traced in 1.23 to 1.26 ms in Node with them kept, 1.16 to
    // 1.21 ms made; natively 0.73 and 0.63 to 0.68 ms).
    builder.reserve(at_least)?;
    for k in 0..notes.chords.len() {
        let (from, to) = notes.ends(k);
        let run = RunChord {
            builder: &mut builder,
            ideal: || chords.ideal_between(&from, &to),
        };
        stepper
            .with_stepper(from.point, to.point, run)
            .expect("not ByRequest")
            .map_err(|error| *error)?;
    }
    let (segment, ideal, start) = (Rc::clone(&chords), Rc::clone(&chords), chords);
    Ok(builder
        .finish(id)
        .with_note_prefix(Rc::new(move |k| notes.prefix(k)))
        .with_segment_maker(
            Rc::new(move |k| segment.made(k)),
            Rc::new(move |k| ideal.ideal_of(k)),
            Rc::new(move |k| start.notes.ends(k).0.point),
        ))
}

/// What makes an arc's chords again when read: their ends (the notes'
/// vertices), their stepper and the arc they stand for.
struct Chords {
    notes: Rc<ChordNotes>,
    stepper: LineStepper,
    /// The arc as a helix of its rise (0 for a flat arc).
    helix: HelixPath,
    /// Whether the chords are measured against the helix (a rising arc)
    /// rather than the arc in its plane.
    helical: bool,
}

impl Chords {
    /// The piece of the arc (or helix) between two vertices.
    fn ideal_between(&self, from: &Vertex, to: &Vertex) -> IdealPath {
        if self.helical {
            IdealPath::Helix(self.helix.piece(from.fraction, to.fraction))
        } else {
            let arc = &self.helix.arc;
            let sweep = arc.sweep_rad;
            IdealPath::Arc(arc.piece(
                arc.start_rad + sweep * from.fraction,
                sweep * (to.fraction - from.fraction),
            ))
        }
    }

    /// Chord `k`'s piece of the arc.
    fn ideal_of(&self, k: usize) -> IdealPath {
        let (from, to) = self.notes.ends(k);
        self.ideal_between(&from, &to)
    }

    /// Chord `k` as it was run: from its first vertex, its stepper before
    /// its first step, against its piece of the arc.
    fn made(&self, k: usize) -> MadeSegment {
        let (from, to) = self.notes.ends(k);
        let make = MakeSegment {
            start: from.point,
            ideal: self.ideal_of(k),
        };
        self.stepper
            .with_stepper(from.point, to.point, make)
            .expect("a chord made when read ran in place, by a LineStepper")
    }
}

/// What a learner reads before each chord: the arc's chording before the
/// first, then the chord's ends and the part of the arc it stands for. Kept
/// as the arc and its vertices, each note written when it is read (most
/// traces never read one): the intro sentence formatted at trace time took
/// about 1% of the r = 300,000 circle's trace in 1,720 chords, which the
/// circle itself does not pay.
struct ChordNotes {
    spec: ArcSpec,
    chording: Chording,
    /// Chords the rule counted, and the chords taken (more for a full
    /// circle counted under [`MIN_FULL_CIRCLE_CHORDS`]); `chords` holds
    /// fewer where a vertex rounded onto the one before.
    counted: u64,
    taken: u64,
    chords: Vec<Vertex>,
    line: &'static str,
}

impl ChordNotes {
    /// Chord `k`'s first and last vertices.
    fn ends(&self, k: usize) -> (Vertex, Vertex) {
        let from = k.checked_sub(1).map_or(
            Vertex {
                point: self.spec.from,
                fraction: 0.0,
            },
            |j| self.chords[j],
        );
        (from, self.chords[k])
    }

    /// The sentence before the first chord's note: the arc and how its
    /// chords were counted.
    fn intro(&self) -> String {
        let (spec, n, counted) = (&self.spec, self.taken, self.counted);
        let sagitta = spec.radius() * (1.0 - (spec.sweep_rad().abs() / (2 * n) as f64).cos());
        format!(
            "{}. {}{}, each of sagitta {sagitta:.3}; vertices are the arc points at i/{n} of the sweep, rounded to the grid. ",
            spec.describe(),
            self.chording.describe(counted),
            if n > counted {
                format!(", raised to {n}, the fewest that go around a full circle")
            } else {
                String::new()
            },
        )
    }

    /// The start of chord `k`'s note (its stepper's own note follows).
    fn prefix(&self, k: usize) -> String {
        let (from, to) = self.ends(k);
        let (start_rad, sweep_rad) = (self.spec.start_rad(), self.spec.sweep_rad());
        format!(
            "{}Chord {} of {}: {} -> {}, the arc from {:.1}° to {:.1}°, stepped by {}:",
            if k == 0 { self.intro() } else { String::new() },
            k + 1,
            self.chords.len(),
            from.point,
            to.point,
            degrees(start_rad + sweep_rad * from.fraction),
            degrees(start_rad + sweep_rad * to.fraction),
            self.line,
        )
    }
}

/// Runs one chord's line stepper into the arc's trace.
struct RunChord<'a, I> {
    builder: &'a mut TraceBuilder,
    /// The chord's piece of the arc, asked for only if the chord is kept.
    ideal: I,
}

impl<I: FnOnce() -> IdealPath> StepperVisitor for RunChord<'_, I> {
    /// The error boxed: a chord's result is then a word, where an
    /// [`Error`] by value, merged from the line algorithms' arms of
    /// [`LineStepper::with_stepper`], was copied twice a chord, failed or
    /// not (in wasm memory.copy calls into the engine: 5,321 a trace of
    /// the r = 300,000 circle in 1,720 chords, 1,881 with it boxed).
    type Out = Result<(), Box<Error>>;
    fn visit<S: Stepper>(self, stepper: S) -> Self::Out {
        self.builder
            .run_made_when_read(stepper, self.ideal)
            .map_err(Box::new)
    }
}

/// The chords of a line algorithm without a [`LineStepper`] (liu-float):
/// each the trace the catalogue gives for it, within what is left of
/// maxSteps (so a too-long arc fails at the chord that passes the limit,
/// before anything larger is allocated), then appended.
fn by_requests(
    builder: &mut TraceBuilder,
    notes: &ChordNotes,
    line_request: &Request,
    line_info: &AlgorithmInfo,
    find: Find,
    ideal_of: impl Fn(&Vertex, &Vertex) -> IdealPath,
) -> Result<(), Error> {
    let mut parts = Vec::with_capacity(notes.chords.len());
    let mut total_steps = 0;
    let mut from = Vertex {
        point: notes.spec.from,
        fraction: 0.0,
    };
    for to in &notes.chords {
        let mut options = line_request.options().clone();
        options.insert("from".into(), Value::from(from.point.coords()));
        options.insert("to".into(), Value::from(to.point.coords()));
        options.insert(
            "maxSteps".into(),
            Value::from(builder.max_steps() - total_steps),
        );
        let part = (line_info.trace)(&Request::new(line_info.id, options), find).map_err(|e| {
            if e.field_name() == Some("maxSteps") {
                builder.too_long(builder.max_steps() + 1)
            } else {
                e
            }
        })?;
        total_steps += part.steps();
        parts.push((part, ideal_of(&from, to)));
        from = *to;
    }
    builder.reserve(total_steps)?;
    for (part, ideal) in parts {
        builder.append(part, |segment| segment.ideal = ideal.clone())?;
    }
    Ok(())
}

/// The [`Find`] of the unit tests here and in `helix`: the chords' default
/// line algorithm and no other (the catalogue, which imports this file, is
/// not theirs to import).
#[cfg(test)]
pub(crate) fn find_regions(id: &str) -> Result<&'static AlgorithmInfo, Error> {
    match id {
        "regions" => Ok(&crate::line::regions_wang::INFO),
        _ => crate::algorithm_info::find_none(id),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algorithm_info::find_none;

    /// Everything a reader gets of a trace, as text.
    fn seen(t: &Trace) -> Vec<String> {
        let mut out = vec![
            serde_json::to_string(&t.summary()).unwrap(),
            serde_json::to_string(&t.legend()).unwrap(),
            serde_json::to_string(&t.segment_summaries()).unwrap(),
            format!("{:?}", t.points_flat(0, t.steps() + 1)),
            format!("{:?}", t.decisions_flat(0, t.steps())),
            format!("{:?}", t.metrics()),
            format!("{:?}", t.ideal_polyline()),
        ];
        // Every 37th step's explanation (each replays its segment's
        // stepper from its last state), and the last one.
        out.extend(
            (0..t.steps())
                .step_by(37)
                .chain(t.steps().checked_sub(1))
                .map(|k| t.explain(k)),
        );
        out
    }

    /// The chords' line algorithms, for the test below (the catalogue,
    /// which imports this file, is not the tests' to import).
    fn find_line(id: &str) -> Result<&'static AlgorithmInfo, Error> {
        use crate::line::*;
        [
            &regions_wang::INFO,
            &bresenham3d::INFO,
            &nd::INFO,
            &liu_float::INFO,
            &dda::INFO,
            &greedy::INFO,
            &walk6::INFO,
        ]
        .into_iter()
        .find(|info| info.id == id)
        .map_or_else(|| find_none(id), Ok)
    }

    /// Chords run in place read back as the catalogue's traces of the
    /// chords appended, for every line algorithm, with and without a tie
    /// option, on an arc and a helix, chords long and short (a chord past
    /// a checkpoint interval keeps stepper states).
    #[test]
    fn chords_in_place_read_back_as_the_catalogue_s_chords() {
        for &line in LINE_ALGORITHMS {
            for (algorithm, extra, to) in [
                ("arc-segments", r#""tolerance": 0.3"#, "[0, 90, 0]"),
                ("arc-segments", r#""segmentLength": 9000"#, "[0, 9000, 0]"),
                (
                    "helix",
                    r#""method": "segments", "segmentLength": 50"#,
                    "[0, 90, 40]",
                ),
            ] {
                let from = if to == "[0, 9000, 0]" {
                    "[9000, 0, 0]"
                } else {
                    "[90, 0, 0]"
                };
                for tie in ["", r#", "tie": "hold""#] {
                    let json = format!(
                        r#"{{"algorithm": "{algorithm}", "from": {from}, "to": {to}, "center": [0, 0, 0], "lineAlgorithm": "{line}", {extra}{tie}}}"#
                    );
                    let req = Request::from_json(&json).unwrap();
                    let helical = algorithm == "helix";
                    let spec = ArcSpec::parse(&req, helical, 3).unwrap();
                    let fast = chords_by(algorithm, &req, &spec, helical, find_line, true);
                    let slow = chords_by(algorithm, &req, &spec, helical, find_line, false);
                    match (fast, slow) {
                        (Ok(a), Ok(b)) => assert_eq!(seen(&a), seen(&b), "{json}"),
                        (a, b) => assert_eq!(a.err(), b.err(), "{json}"),
                    }
                }
            }
        }
    }

    /// A chord run in place that parts from the steps it is to follow
    /// fails as the catalogue's chords do, at the same step, whichever
    /// chord it is in (its error passed out boxed).
    #[test]
    fn chords_in_place_fail_where_the_catalogue_s_chords_do() {
        let json = r#"{"algorithm": "arc-segments", "from": [90, 0, 0], "to": [0, 90, 0], "center": [0, 0, 0], "segmentLength": 20}"#;
        let req = Request::from_json(json).unwrap();
        let spec = ArcSpec::parse(&req, false, 3).unwrap();
        let run = |req: &Request, in_place| chords_by(ID, req, &spec, false, find_line, in_place);
        let steps = run(&req, true).unwrap().step_range(0, 90).to_vec();
        for wrong_at in [0, 25, 89] {
            let mut followed = steps.clone();
            followed[wrong_at] = crate::grid::Step(followed[wrong_at].0 ^ 0b100);
            let req = req.clone().following(followed.into());
            let error = run(&req, true).err();
            assert_eq!(error, run(&req, false).err(), "wrong at {wrong_at}");
            let error = error.map(|e| e.to_string()).unwrap_or_default();
            assert!(error.contains(&format!("at step {wrong_at}")), "{error}");
        }
    }

    /// A tie given for chords whose line algorithm has no tie rule was
    /// dropped: greedy's chords with tie hold were its chords without it.
    #[test]
    fn a_tie_for_a_line_algorithm_without_one_is_refused() {
        for line in ["greedy", "walk6", "dda"] {
            for (algorithm, extra) in [("arc-segments", ""), ("helix", r#", "method": "segments""#)]
            {
                let json = format!(
                    r#"{{"algorithm": "{algorithm}", "from": [100, 0, 0], "to": [0, 100, 0], "center": [0, 0, 0], "lineAlgorithm": "{line}", "tie": "hold"{extra}}}"#
                );
                let req = Request::from_json(&json).unwrap();
                let spec = ArcSpec::parse(&req, algorithm == "helix", 3).unwrap();
                let Err(error) = chords_by(
                    algorithm,
                    &req,
                    &spec,
                    algorithm == "helix",
                    find_line,
                    true,
                ) else {
                    panic!("{json}: stepped");
                };
                assert_eq!(
                    error.to_string(),
                    format!(
                        "tie: {line}, the chords' lineAlgorithm, has no tie rule to pass it to; tie is for regions, bresenham3d, nd, liu-float"
                    ),
                    "{json}"
                );
            }
        }
    }

    use crate::arc::angle::atan3;
    use std::f64::consts::{PI, TAU};

    fn spec(json: &str) -> ArcSpec {
        ArcSpec::parse(&Request::from_json(json).unwrap(), false, 3).unwrap()
    }

    /// The sweep as the post's Implementation computes it (dir > 0 is the
    /// post's ARC_CW, an increasing angle), printed line for line.
    fn printed_sweep(angle1: f64, angle2: f64, dir: f64) -> f64 {
        let (mut angle1, mut angle2) = (angle1, angle2);
        let sweep = angle2 - angle1;
        if dir > 0.0 && sweep < 0.0 {
            angle2 += TAU;
        } else if dir < 0.0 {
            angle1 += TAU;
        }
        angle2 - angle1
    }

    /// The earlier snippet of the same post.
    fn snippet_sweep(angle1: f64, angle2: f64, dir: f64) -> f64 {
        let (mut angle1, mut angle2) = (angle1, angle2);
        let sweep = angle2 - angle1;
        if dir > 0.0 && sweep < 0.0 {
            angle2 += TAU;
        } else if dir < 0.0 && sweep > 0.0 {
            angle1 += TAU;
        }
        angle2 - angle1
    }

    #[test]
    fn the_printed_sweep_fix_up_adds_a_turn() {
        // From (0, 5) to (5, 0) around the origin, the short way: decreasing
        // angle, G02 in G-code (y up), the post's ARC_CCW (dir < 0).
        let (angle1, angle2) = (atan3(5.0, 0.0), atan3(0.0, 5.0));
        assert_eq!((angle1, angle2), (PI / 2.0, 0.0));
        // The printed code turns the quarter arc into 450°.
        assert!((printed_sweep(angle1, angle2, -1.0) + 2.5 * PI).abs() < 1e-12);
        assert!((snippet_sweep(angle1, angle2, -1.0) + 0.5 * PI).abs() < 1e-12);
        let s = spec(
            r#"{"algorithm":"arc-segments","from":[0,5,0],"to":[5,0,0],"center":[0,0,0],"dir":"cw"}"#,
        );
        assert!((s.sweep_rad() + 0.5 * PI).abs() < 1e-12);
        // With the blog's length rule and segment 1, that is 39 chords
        // (floor(2.5π × 5)) instead of 7 (floor(0.5π × 5)).
        let chords = |sweep: f64| Chording::Length(1.0).chords(5.0, sweep).unwrap();
        assert_eq!(
            (
                chords(printed_sweep(angle1, angle2, -1.0)),
                chords(s.sweep_rad())
            ),
            (39, 7)
        );
        // Both rules agree when the fix-up is needed: increasing angle from
        // (5, 0) to (0, -5) is 270° (the post's ARC_CW, G03 here).
        let (a1, a2) = (atan3(0.0, 5.0), atan3(-5.0, 0.0));
        assert!((printed_sweep(a1, a2, 1.0) - 1.5 * PI).abs() < 1e-12);
        let s = spec(
            r#"{"algorithm":"arc-segments","from":[5,0,0],"to":[0,-5,0],"center":[0,0,0],"dir":"ccw"}"#,
        );
        assert!((s.sweep_rad() - 1.5 * PI).abs() < 1e-12);
    }

    #[test]
    fn chord_counts_follow_the_blog_and_grbl() {
        // Quarter circle r = 10: length 5π = 15.71; segment 5 gives
        // floor(3.14) = 3 chords.
        assert_eq!(Chording::Length(5.0).chords(10.0, PI / 2.0).unwrap(), 3);
        // Grbl, r = 100, quarter, t = 0.5: 0.5 × 157.08 / sqrt(0.5 × 199.5)
        // = 78.54 / 9.987 = 7.86, floor 7.
        assert_eq!(Chording::Tolerance(0.5).chords(100.0, PI / 2.0).unwrap(), 7);
        // Too short for one full chord: still one chord, to the end.
        assert_eq!(Chording::Length(100.0).chords(10.0, 0.1).unwrap(), 1);
        let e = Chording::Length(1.0)
            .chords((1 << 20) as f64, TAU)
            .unwrap_err();
        assert_eq!(e.field_name(), Some("segmentLength"));
        assert!(e.to_string().contains("6588397 chords"), "{e}");
        // The count and the bound as numbers, for a G-code program to word
        // its own refusal (it read them back out of this message before).
        assert_eq!(
            e.too_many_chords.as_deref(),
            Some(&TooManyChords {
                chords: 6588397.0,
                most: MAX_CHORDS
            })
        );
        // Past what a double counts: said so, not "inf chords".
        let e = Chording::Length(1e-320).chords(20.0, PI).unwrap_err();
        assert_eq!(
            e.too_many_chords.as_ref().map(|refusal| refusal.chords),
            Some(f64::INFINITY)
        );
        assert!(
            e.to_string()
                .contains("splits this arc into more chords than can be counted, more than 65536"),
            "{e}"
        );
        let e = Chording::Tolerance(30.0).chords(10.0, PI).unwrap_err();
        assert_eq!(
            e.to_string(),
            "tolerance: must be less than the diameter 20.000, got 30"
        );
        assert_eq!(e.too_many_chords, None);
        // A huge value as JavaScript writes it, not in 301 digits.
        let e = Chording::Tolerance(1e300).chords(10.0, PI).unwrap_err();
        assert_eq!(
            e.to_string(),
            "tolerance: must be less than the diameter 20.000, got 1e300"
        );
        let both =
            Request::from_json(r#"{"algorithm":"arc-segments","segmentLength":2,"tolerance":1}"#)
                .unwrap();
        assert_eq!(
            Chording::parse(&both).unwrap_err().to_string(),
            "tolerance: give segmentLength or tolerance, not both"
        );
    }

    #[test]
    fn vertices_are_rounded_arc_points_then_the_end() {
        // Quarter circle r = 10 in 3 chords: 30° -> (8.66, 5) -> (9, 5);
        // 60° -> (5, 8.66) -> (5, 9); then the end (0, 10).
        let s =
            spec(r#"{"algorithm":"arc-segments","from":[10,0,0],"to":[0,10,0],"center":[0,0,0]}"#);
        let v: Vec<Point> = vertices(&s, 3).iter().map(|v| v.point).collect();
        assert_eq!(
            v,
            [
                Point::new(&[9, 5, 0]),
                Point::new(&[5, 9, 0]),
                Point::new(&[0, 10, 0])
            ]
        );
        // In G18 (z, x) clockwise from z = 10 to x = -10: 30° steps of
        // decreasing angle atan2(x, z): (z, x) = (8.66, -5) -> (9, -5).
        let s = spec(
            r#"{"algorithm":"arc-segments","from":[0,4,10],"to":[-10,4,0],"center":[0,0,0],"plane":"zx","dir":"cw"}"#,
        );
        let v: Vec<Point> = vertices(&s, 3).iter().map(|v| v.point).collect();
        assert_eq!(
            v,
            [
                Point::new(&[-5, 4, 9]),
                Point::new(&[-9, 4, 5]),
                Point::new(&[-10, 4, 0])
            ]
        );
        // Chords shorter than a cell: vertices that round onto the previous
        // one are dropped. r = 2, full circle, 64 chords: the rounded arc
        // points are the 16 cells (2, 0), (2, 1), (1, 1), (1, 2), ... of
        // the ring around the circle, each kept once.
        let s =
            spec(r#"{"algorithm":"arc-segments","from":[2,0,0],"to":[2,0,0],"center":[0,0,0]}"#);
        let v = vertices(&s, 64);
        assert_eq!(v.len(), 16);
        assert!(v.windows(2).all(|w| w[0].point != w[1].point));
        assert_eq!(v.last().unwrap().point, Point::new(&[2, 0, 0]));
    }

    #[test]
    fn vertex_halves_go_away_from_zero_whatever_the_float_error() {
        // A rise of 45 in 30 chords: the 21st vertex is 31.5 up, where
        // 45 × (21/30) is 31.499999999999996 in f64 (it went to 31).
        let json = r#"{"algorithm":"helix","from":[10,0,0],"to":[10,0,45],"center":[0,0,0]}"#;
        let s = ArcSpec::parse(&Request::from_json(json).unwrap(), true, 3).unwrap();
        assert_eq!(vertices(&s, 30)[20].point.get(2), 32);
        let heights: Vec<i64> = vertices(&s, 30).iter().map(|v| v.point.get(2)).collect();
        let exact: Vec<i64> = (1..=30).map(|i| (2 * 45 * i + 30) / 60).collect();
        assert_eq!(heights, exact);
        // In the plane: r = 1 about (y, z) = (-7, -39), from 270° a
        // counterclockwise 315° in 3 chords: the second vertex is at 120°,
        // y = -7 + cos 120° = -7.5 exactly, computed a little above it
        // (-7.499999999999999): -8 by the rule, where it went to -7.
        let s = spec(
            r#"{"algorithm":"arc-segments","from":[-6,-7,-40],"to":[-6,-8,-40],"center":[7,-7,-39],"plane":"yz","dir":"ccw"}"#,
        );
        let v: Vec<Point> = vertices(&s, 3).iter().map(|v| v.point).collect();
        assert_eq!(
            v,
            [
                Point::new(&[-6, -6, -39]),
                Point::new(&[-6, -8, -38]),
                Point::new(&[-6, -8, -40])
            ]
        );
        // Over many turns too: a circle of r = 3 in chords of 30°, 101
        // turns, has every coordinate 0, ±2 (3 sin 30° = 1.5) or ±3, on
        // the last turn as on the first. Found by a review.
        let s = spec(
            r#"{"algorithm":"arc-segments","from":[3,0,0],"to":[3,0,0],"center":[0,0,0],"turns":100}"#,
        );
        let wrong: Vec<Point> = vertices(&s, 12 * 101)
            .iter()
            .map(|v| v.point)
            .filter(|p| (0..2).any(|a| ![0, 2, 3].contains(&p.get(a).abs())))
            .collect();
        assert_eq!(wrong, []);
    }

    #[test]
    fn each_chord_is_the_line_algorithm_s_own_trace() {
        let t = INFO
            .trace_json(
                r#"{"algorithm":"arc-segments","from":[10,0,0],"to":[0,10,0],"center":[0,0,0],"segmentLength":5}"#,
                find_regions,
            )
            .unwrap();
        let ends = [[10, 0, 0], [9, 5, 0], [5, 9, 0], [0, 10, 0]];
        assert_eq!(t.segment_count(), 3);
        for (k, segment) in t.segments().enumerate() {
            let line = crate::line::regions_wang::INFO
                .trace_json(
                    &format!(
                        r#"{{"algorithm":"regions","from":{:?},"to":{:?}}}"#,
                        ends[k],
                        ends[k + 1]
                    ),
                    find_none,
                )
                .unwrap();
            let first = segment.first_step;
            assert_eq!(
                t.step_range(first, first + segment.steps),
                line.step_range(0, line.steps())
            );
            // Bit patterns, so that NaN (a column that does not apply) compares equal.
            let bits = |columns: Vec<Vec<f64>>| -> Vec<Vec<u64>> {
                columns
                    .iter()
                    .map(|c| c.iter().map(|v| v.to_bits()).collect())
                    .collect()
            };
            assert_eq!(
                bits(t.decisions(first, first + segment.steps).columns),
                bits(line.decisions(0, line.steps()).columns)
            );
            assert!(matches!(segment.ideal, IdealPath::Arc(_)));
        }
        assert_eq!(t.end(), Point::new(&[0, 10, 0]));
        let note = t.segment_note(0);
        assert!(
            note.contains("floor(arc length / segmentLength 5) gives 3 chords"),
            "{note}"
        );
        assert!(
            note.contains("Chord 1 of 3: (10, 0, 0) -> (9, 5, 0), the arc from 0.0° to 30.0°"),
            "{note}"
        );
    }
}
