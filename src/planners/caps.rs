//! What a planner can do, as data (OMPL's `PlannerSpecs`): the page draws, charts, explains and
//! offers queries and overlays from this, never by comparing planner names.
//!
//! Each [`PlannerSpec`](super::PlannerSpec) carries one [`Capabilities`]. What the registry already
//! says is derived rather than restated: a planner samples when it takes the sampler's group, and
//! takes tree variants when it takes the tree group ([`PlannerSpec::samples`](super::PlannerSpec::samples)).
//! A test runs every planner and checks that the events it emits are the ones it declares.

use crate::events::EventKind;

/// The family of method, as the courses group them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    /// Sampling-based trees (RRT, EST and their kin).
    Tree,
    /// Sampling-based roadmaps (PRM and its kin).
    Roadmap,
    /// Cell decompositions searched cell to cell.
    Cells,
    /// Potential fields.
    Field,
    /// Exact (combinatorial) methods.
    Exact,
}

impl Family {
    /// The name the page reads.
    pub fn as_str(self) -> &'static str {
        match self {
            Family::Tree => "tree",
            Family::Roadmap => "roadmap",
            Family::Cells => "cells",
            Family::Field => "field",
            Family::Exact => "exact",
        }
    }
}

/// What a planner's records draw (the page's adapter maps each to a drawing).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Draws {
    /// Trees of nodes and edges.
    Tree,
    /// A roadmap: milestones and edges, searched for each query.
    Roadmap,
    /// Cells of a decomposition, with their search.
    Cells,
    /// A potential field, descended.
    Field,
    /// The cells of an occupancy grid.
    Grid,
    /// An exact graph (visibility graph) and its search.
    ExactGraph,
}

impl Draws {
    /// The name the page reads.
    pub fn as_str(self) -> &'static str {
        match self {
            Draws::Tree => "tree",
            Draws::Roadmap => "roadmap",
            Draws::Cells => "cells",
            Draws::Field => "field",
            Draws::Grid => "grid",
            Draws::ExactGraph => "exact-graph",
        }
    }
}

/// One entry of a planner's legend: a label, the palette's colour role, the mark's shape.
#[derive(Clone, Copy, Debug)]
pub struct LegendItem {
    /// What the mark means.
    pub label: &'static str,
    /// The colour's role in the page's palette (`www/draw/palette.js`, `PALETTE`).
    pub color: &'static str,
    /// The mark: `line`, `box`, `ring`, `dot`, `cross`, `dash`, `thick`.
    pub shape: &'static str,
}

impl LegendItem {
    /// A line in colour role `color`.
    pub const fn line(label: &'static str, color: &'static str) -> LegendItem {
        LegendItem { label, color, shape: "line" }
    }
    /// A box in colour role `color`.
    pub const fn boxed(label: &'static str, color: &'static str) -> LegendItem {
        LegendItem { label, color, shape: "box" }
    }
    /// As JSON `{label, color, shape}`.
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({"label": self.label, "color": self.color, "shape": self.shape})
    }
    /// A ring in colour role `color`.
    pub const fn ring(label: &'static str, color: &'static str) -> LegendItem {
        LegendItem { label, color, shape: "ring" }
    }
}

/// One tree's legend entry (tree 0 only).
pub const ONE_TREE: &[LegendItem] = &[LegendItem::line("tree", "tree0")];
/// Two trees, from the start and from the goal.
pub const TWO_TREES: &[LegendItem] = &[
    LegendItem::line("tree from the start (tree 0)", "tree0"),
    LegendItem::line("tree from the goal (tree 1)", "tree1"),
];
/// A roadmap and its search.
pub const ROADMAP: &[LegendItem] = &[
    LegendItem::line("roadmap: milestones, checked edges", "tree0"),
    LegendItem::line("search's latest path", "queryPath"),
];

/// What a planner can do and what it shows.
#[derive(Clone, Copy, Debug)]
pub struct Capabilities {
    /// Its family of method.
    pub family: Family,
    /// What its records draw.
    pub draws: Draws,
    /// Trees it grows, for naming them: 2 for a tree from the start and one from the goal, 1 for
    /// one tree (a search's, a descent's with its random walks), 0 for a roadmap.
    pub trees: u8,
    /// It keeps improving after a first solution (a best path so far).
    pub improves: bool,
    /// What its chart shows, if it reports a measure as it improves (`cost`, `coverage`).
    pub chart: Option<&'static str>,
    /// It answers further queries on what it built ([`super::Planner::query`]).
    pub queries: bool,
    /// It can conclude that there is no path ([`super::Planner::gave_up`]) by its method.
    pub proves_no_path: bool,
    /// The event kinds it emits (besides those of the sampler and the run: sample, rejected
    /// sample, raw try, solved, smoothing).
    pub events: EventSet,
    /// The key of its pseudocode in the page's table (`www/run/pseudocode.js`).
    pub pseudocode: &'static str,
    /// Its legend entries for the lines it draws (trees, roadmap, graph), beside the paths.
    pub legend: &'static [LegendItem],
    /// Its legend entries for the marks of its cells and fields, after the robot's.
    pub marks: &'static [LegendItem],
    /// The overlays it offers beyond those its sampler and tree variants imply (`rewires`,
    /// `best`, `seen`, `fov`, `cells`, `region`, `density`, `heat`, `arrows`).
    pub overlays: &'static [&'static str],
}

/// A set of event kinds, built in constant expressions (`of`, `with`), so a planner declares its
/// events as a shared set plus its own.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EventSet(u64);

impl EventSet {
    /// The set of `kinds`.
    pub const fn of(kinds: &[EventKind]) -> EventSet {
        EventSet(0).with(kinds)
    }
    /// This set and `kinds`.
    pub const fn with(self, kinds: &[EventKind]) -> EventSet {
        let mut bits = self.0;
        let mut i = 0;
        while i < kinds.len() {
            bits |= 1 << kinds[i] as u8;
            i += 1;
        }
        EventSet(bits)
    }
    /// Whether `kind` is in the set.
    pub fn contains(self, kind: EventKind) -> bool {
        self.0 & (1 << kind as u8) != 0
    }
    /// The kinds in the set, in [`EventKind::ALL`]'s order, with their names.
    pub fn iter(self) -> impl Iterator<Item = (EventKind, &'static str)> {
        EventKind::ALL.into_iter().filter(move |(k, _)| self.contains(*k))
    }
}

/// The events of a sampling tree grown through [`super::Tree`]: its sampler's (sample, rejected
/// sample, raw try) and the tree's growth.
pub const SAMPLING_TREE: EventSet = EventSet::of(&[
    EventKind::Sample,
    EventKind::SampleRejected,
    EventKind::SampleTry,
    EventKind::NodeAdded,
    EventKind::Collision,
    EventKind::Nearest,
    EventKind::Steer,
    EventKind::Solved,
]);

impl Capabilities {
    /// As JSON, with what the spec derives: `samples`, `tree_variants`.
    pub fn to_json(&self, samples: bool, tree_variants: bool) -> serde_json::Value {
        serde_json::json!({
            "family": self.family.as_str(),
            "draws": self.draws.as_str(),
            "trees": self.trees,
            "samples": samples,
            "tree_variants": tree_variants,
            "improves": self.improves,
            "chart": self.chart,
            "queries": self.queries,
            "proves_no_path": self.proves_no_path,
            "events": self.events.iter().map(|(_, name)| name).collect::<Vec<_>>(),
            "pseudocode": self.pseudocode,
            "legend": self.legend.iter().map(LegendItem::to_json).collect::<Vec<_>>(),
            "marks": self.marks.iter().map(LegendItem::to_json).collect::<Vec<_>>(),
            "overlays": self.overlays,
        })
    }
}
