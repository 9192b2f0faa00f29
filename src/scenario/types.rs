use crate::math::Real;
use serde::Serialize;
use serde_json::{Map, Value};

/// The format tag of version 1.
pub const FORMAT: &str = "planarium-scenario/1";

/// A parsed and validated scenario (the contract's document, in Rust types).
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Scenario {
    /// Always [`FORMAT`].
    pub format: String,
    /// Shown as the scenario's title.
    pub name: String,
    /// Plain text shown under the canvas.
    #[serde(skip_serializing_if = "String::is_empty")]
    pub notes: String,
    /// `[xmin, ymin, xmax, ymax]`.
    pub bounds: [Real; 4],
    /// Closed obstacles.
    pub obstacles: Vec<ObstacleSpec>,
    /// Closed 3-D obstacles, for a spatial arm (optional).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub obstacles3d: Vec<SolidSpec>,
    /// The robot.
    pub robot: RobotSpec,
    /// Start state.
    pub start: Vec<Real>,
    /// Goal state (absent only for inspection tasks).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub goal: Option<Vec<Real>>,
    /// Distance in the robot's metric within which the goal counts as reached.
    pub goal_tolerance: Real,
    /// Largest step between two checked states along a motion, in the robot's metric.
    pub resolution: Real,
    /// Keep the whole body (not only the reference point) inside the bounds.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub body_in_bounds: bool,
    /// Obstacles are open sets: touching their boundary is allowed (the Technion and ASV courses).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub touching_allowed: bool,
    /// Optional inspection task.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub inspection: Option<Inspection>,
    /// Planner defaults selected when the scenario opens.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub planner: Option<PlannerDefaults>,
    /// The pixel grid of the occupancy map the scenario came from (optional).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub map: Option<MapGrid>,
}

/// The optional `map` block: the pixel grid of an imported occupancy map (`io::occupancy`), so
/// grid-search's default cell is one pixel, aligned with the image.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct MapGrid {
    /// Side of a pixel.
    pub resolution: Real,
    /// The lower left corner of the lower left pixel `[x, y]`.
    pub origin: [Real; 2],
}

/// One obstacle, as the contract writes it (`{"rect": [...]}` and so on).
#[derive(Clone, Debug, Serialize, PartialEq)]
#[serde(rename_all = "lowercase")]
pub enum ObstacleSpec {
    /// `[x0, y0, x1, y1]`, corners in any order.
    Rect([Real; 4]),
    /// Simple polygon, convex or not.
    Polygon(Vec<[Real; 2]>),
    /// `[cx, cy, r]`.
    Circle([Real; 3]),
    /// `[x0, y0, x1, y1]`, a wall of zero thickness.
    Segment([Real; 4]),
}

/// The robot block.
#[derive(Clone, Debug, Serialize, PartialEq)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum RobotSpec {
    /// A point robot; state `[x, y]`.
    Point,
    /// A rigid polygon; state `[x, y, theta]`.
    Rigid {
        /// Polygon in the body frame, rotating about the origin.
        footprint: Vec<[Real; 2]>,
        /// Weight of rotation in the metric (default: the footprint's radius).
        #[serde(skip_serializing_if = "Option::is_none")]
        rotation_weight: Option<Real>,
    },
    /// A fixed-base planar arm; state `[q1, ..., qn]`, each angle relative to the previous link.
    Arm {
        /// Base position.
        base: [Real; 2],
        /// Link lengths.
        links: Vec<Real>,
        /// Per joint `[lo, hi]`, or `None` for a joint that wraps around.
        limits: Vec<Option<[Real; 2]>>,
        /// Whether links may not cross each other (default true).
        self_collision: bool,
        /// The metric: `joint` (Euclidean in joint space), `chain` (sum of link-end moves, OMPL's
        /// kinematic chain), `max` (the largest joint-point move) or `fk` (the Euclidean norm of
        /// the stacked link-end differences, report 004's distance); default `chain`.
        metric: String,
        /// A short extra segment continuing the last link, checked for collisions (OMPL's chain
        /// benchmark uses 0.001); default 0.
        #[serde(skip_serializing_if = "is_zero")]
        tip: Real,
    },
    /// A chain of `count` vehicles joined by brooms; state `[x1, y1, ..., xn, yn]`.
    Asv {
        /// Number of vehicles.
        count: usize,
        /// Length of every broom.
        broom: Real,
        /// Smallest area of the closed polygon (default `π·(0.007·(n−1))²`).
        min_area: Real,
        /// Whether the closed polygon must be convex (default true).
        convex: bool,
        /// Largest move of any vehicle in one primitive step (default 0.001).
        max_step: Real,
    },
    /// A serial chain of revolute joints in 3-D (classic Denavit–Hartenberg rows); state
    /// `[q1, ..., qn]`, radians.
    #[serde(rename = "spatial-arm")]
    SpatialArm(Box<SpatialArmSpec>),
}

/// The `spatial-arm` robot block (see `docs/scenario-format.md`).
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct SpatialArmSpec {
    /// Link 0's frame in the world.
    pub base: PoseSpec,
    /// One row per joint.
    pub joints: Vec<DhJoint>,
    /// `joints + 1` links: link 0 the base, link `k` moved by joint `k`.
    pub links: Vec<LinkSpec>,
    /// Link pairs `[i, j]` (`i < j`) never tested against each other.
    pub ignore: Vec<[usize; 2]>,
    /// Links never tested against the scene.
    pub exempt: Vec<usize>,
    /// The tool centre point in the last link's frame.
    pub tool: [Real; 3],
    /// The metric over the joint angles: `joint` (Euclidean, radians).
    pub metric: String,
}

/// A pose: a translation and a rotation `[rx, ry, rz]` (radians, `Rz(rz)·Ry(ry)·Rx(rx)`).
#[derive(Clone, Copy, Debug, Serialize, PartialEq, Default)]
pub struct PoseSpec {
    /// `[x, y, z]`.
    pub translation: [Real; 3],
    /// `[rx, ry, rz]`.
    pub rotation: [Real; 3],
}

/// One classic Denavit–Hartenberg row: the joint's transform is `Rz(theta + q)·Tz(d)·Tx(a)·Rx(alpha)`.
#[derive(Clone, Copy, Debug, Serialize, PartialEq)]
pub struct DhJoint {
    /// Offset along the previous z axis.
    pub d: Real,
    /// Angle about the previous z axis added to the joint's value.
    pub theta: Real,
    /// Length along the new x axis.
    pub a: Real,
    /// Twist about the new x axis.
    pub alpha: Real,
    /// `[lo, hi]` of the joint's value.
    pub limits: [Real; 2],
}

/// One link's collision geometry, in its own frame.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct LinkSpec {
    /// Its name (default `linkK`).
    pub name: String,
    /// Points whose convex hull collides (empty: none).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub hull: Vec<[Real; 3]>,
    /// Boxes fixed to the link (a tool).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub boxes: Vec<BoxSpec>,
}

/// An axis-aligned box by centre and full size, with an optional name.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct BoxSpec {
    /// Its name ("" when none was given).
    #[serde(skip_serializing_if = "String::is_empty")]
    pub name: String,
    /// `[x, y, z]`.
    pub center: [Real; 3],
    /// Full size `[sx, sy, sz]`, each positive.
    pub size: [Real; 3],
}

/// One 3-D obstacle (`obstacles3d`): a box or a convex hull, optionally named.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct SolidSpec {
    /// Its name ("" when none was given).
    #[serde(skip_serializing_if = "String::is_empty")]
    pub name: String,
    /// The shape.
    #[serde(flatten)]
    pub shape: SolidShape,
}

/// A 3-D obstacle's shape.
#[derive(Clone, Debug, Serialize, PartialEq)]
#[serde(rename_all = "lowercase")]
pub enum SolidShape {
    /// `{"center": [...], "size": [...]}`.
    Box {
        /// `[x, y, z]`.
        center: [Real; 3],
        /// Full size.
        size: [Real; 3],
    },
    /// Points whose convex hull is the obstacle.
    Hull(Vec<[Real; 3]>),
}

fn is_zero(x: &Real) -> bool {
    *x == 0.0
}

impl RobotSpec {
    /// The `kind` name.
    pub fn kind(&self) -> &'static str {
        match self {
            RobotSpec::Point => "point",
            RobotSpec::Rigid { .. } => "rigid",
            RobotSpec::Arm { .. } => "arm",
            RobotSpec::Asv { .. } => "asv",
            RobotSpec::SpatialArm(_) => "spatial-arm",
        }
    }
}

/// The optional inspection block.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Inspection {
    /// Points of interest.
    pub points: Vec<[Real; 2]>,
    /// Field of view, radians, centred on the heading.
    pub fov: Real,
    /// Sensor range.
    pub range: Real,
    /// Fraction of points to see.
    pub coverage: Real,
    /// How a branch's coverage is counted: `continuous` (the default: every state along its
    /// edges, at the motion resolution) or `vertices` (only at the tree's vertices, as the
    /// Technion course's handout defines it).
    #[serde(skip_serializing_if = "is_continuous")]
    pub coverage_mode: String,
    /// A sight line that touches an obstacle's boundary hides the point (the Technion course's
    /// test); default false: only crossing an interior hides it.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub touch_hides: bool,
}

fn is_continuous(m: &str) -> bool {
    m == "continuous"
}

impl Inspection {
    /// Whether coverage is counted at the vertices only.
    pub fn at_vertices(&self) -> bool {
        self.coverage_mode == "vertices"
    }
}

/// The optional planner block: a name, a seed, and parameters by name.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct PlannerDefaults {
    /// Planner name from the registry.
    pub name: String,
    /// Seed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// Parameters by name.
    #[serde(flatten)]
    pub params: Map<String, Value>,
}

impl Scenario {
    /// The scenario as pretty JSON in the contract's form.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).expect("a scenario always serialises")
    }
}
