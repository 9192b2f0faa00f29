//! What happened during planning, as a flat log of fixed-stride `f64` records.
//!
//! Each record is [`STRIDE`] numbers: `[kind, tree, id, parent, x, y, px, py, c0, c1, pc0, pc1]`:
//! the point and its parent's, projected into the workspace (a state's reference point), so the
//! page draws without knowing the robot; then the first two planning coordinates of the state and
//! its parent's, for a configuration-space view of two-dimensional spaces (a 2-joint arm). The worker drains the log after each batch and transfers it as a `Float64Array`; the JS
//! constants in `www/run/events.js` are checked against [`EventKind`] by a test.

use crate::math::{Real, Vec2};

/// Numbers per event record.
pub const STRIDE: usize = 12;

/// The kinds of event (the record's first number).
#[repr(u8)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EventKind {
    /// A sample was drawn (`x, y`: where it is drawn); `id` 1 when it is the goal itself (the goal
    /// bias), 2 a plain uniform draw of the sampler's uniform share, 0 when the sampler's own rule
    /// drew it.
    Sample = 0,
    /// A sample was rejected before growing (invalid state).
    SampleRejected = 1,
    /// A node was added: `id`, `parent`, its point `x, y`, its parent's `px, py`.
    NodeAdded = 2,
    /// A motion was found in collision at the state `c0, c1, …` (its first two numbers), drawn at
    /// `x, y`: where the robot's body meets the obstacle named, or (a point, the map's edge, a
    /// robot's own rule) the state's point. `parent` the node it started from (at `px, py`; -1
    /// when unknown); `id` what blocked it: an obstacle's index in the scenario (≥ 0), -2 the
    /// map's edge, -3 one of the robot's own rules, -1 not known. Both from
    /// [`SpaceInfo::blocked_at`](crate::space_info::SpaceInfo::blocked_at).
    Collision = 3,
    /// The two trees met at `x, y` (`id` in `tree`, `parent`: the node in the other tree).
    TreesConnected = 4,
    /// A solution was found.
    Solved = 5,
    /// A raw draw of the sampler, checked (`id`: 1 free, 0 occupied) at `x, y`.
    SampleTry = 6,
    /// Node `id` got a dynamic domain: radius `px` (∞: none) around its point `x, y`.
    Domain = 7,
    /// Node `id` is exhausted (dropped from nearest-neighbour selection), at `x, y`.
    Exhausted = 8,
    /// Node `id` (at `x, y`) was rewired to parent `parent` (at `px, py`).
    Rewire = 9,
    /// The best solution improved: it ends at node `id`; `parent`: the iteration; `px`: its cost.
    Cost = 10,
    /// Coverage grew: the best branch ends at node `id`; `parent`: the iteration; `px`: the
    /// fraction covered; `py`: points seen.
    Coverage = 11,
    /// Inspection point `id` (at `x, y`) was seen for the first time.
    PointSeen = 12,
    /// A decomposition cell was made: `tree`: its level; `id`; `parent` (-1 at level 0); `x, y`:
    /// its centre; `px`: its [`CellLabel`](crate::planners::hex::CellLabel) (0 free, 1 mixed,
    /// 2 full); `py`: the circumradius of its (unclipped) hexagon; `c0`: the number of outline
    /// vertices, which follow in `ceil(n / 4)` [`CellShape`](EventKind::CellShape) records.
    Cell = 13,
    /// Up to four outline vertices of cell `id`: `x, y, px, py, c0, c1, pc0, pc1` (unused: NaN).
    CellShape = 14,
    /// Cell `id` was judged from cell `parent` (-1: the start): `px`: the verdict (0 passable,
    /// 1 blocked by the step test, 2 visited, 3 outside the region of influence, 4 an
    /// obstacle cell); `py`: for a blocked step, why (1 an obstacle vertex in the t/2 circle, 2 a
    /// vertex in the swept rectangle, 3 an obstacle edge crossing the region, 4 the map's edge).
    CellState = 15,
    /// The potential of candidate cell `id` seen from cell `parent`: `x, y` its centre; `px` the
    /// repulsion `Σ k1/r²`; `py` the trap term `k3/r_j²` (0 when not applied); `c0` the goal
    /// term `−C(1 − k2·α)`; `c1` the total; `pc0` α (radians); `pc1` 1 if the search steps there.
    Potential = 16,
    /// The region of influence: `id` the attempt (0 first); `x, y` its centre; `px` its radius;
    /// `py` the radius at which it stops growing (`d_maxOb + t`); `c0` the obstacles inside it;
    /// `c1` the robot's t (`sqrt(l² + w²)`).
    Region = 17,
    /// A sample of a potential field for the heat map: `id` its index; `x, y` where; `px` the
    /// value; `py`, `c0` its two terms (hexagonal: repulsion, trap term; classic: attraction,
    /// repulsion); `c1, pc0` the direction the robot would move from here (unit, or 0 0);
    /// `pc1` the half-size of the tile it stands for.
    Field = 18,
    /// A local minimum was detected at `x, y` (classic potential field): `id` the escapes so far;
    /// `parent` the chain's node there; `px` the potential there; `py` the distance to the goal;
    /// `c0, c1` the pull of the goal `−∇U_att` and `pc0, pc1` the push of the obstacles
    /// `−∇U_rep` there, in the plane (the forces that cancel).
    Minimum = 19,
    /// A growth step chose node `id` of `tree` to grow (RRT's NEAREST, or the node the tree
    /// variants select): `x, y` its point; `px, py` the target's point (a sample, or a node of the
    /// other tree); `c0` their distance; `c1` the node's dynamic-domain radius (∞: none); `pc0` 1
    /// when the target is a sample, 0 when it is a state of the other tree (CONNECT).
    Nearest = 20,
    /// A growth step steered from node `id` (at `px, py`) toward its target: `x, y` the new
    /// state's point; `c0` the step's length; `c1` the range; `pc0` 1 when the step reaches the
    /// target. The motion is checked next: a `Collision` or a `NodeAdded` follows. `parent` is -1,
    /// except for a ladder step (after a step collided, one that moves only some coordinates):
    /// `parent` the coordinates it moves, `pc1` its try's number, `c1` its length; it was checked
    /// valid, and its `NodeAdded` follows.
    Steer = 21,
    /// A roadmap edge was added between vertices `id` (at `x, y`) and `parent` (at `px, py`):
    /// `tree` 0 when its motion was checked valid (PRM, PRM*), 1 when it is unchecked (Lazy PRM).
    RoadmapEdge = 22,
    /// Lazy PRM checked the edge between vertices `id` (at `x, y`) and `parent` (at `px, py`)
    /// because a query's path used it: `tree` 0 valid, 1 invalid (removed from the roadmap; a
    /// `Collision` follows).
    EdgeChecked = 23,
    /// One edge of the path a roadmap's graph search found, from vertex `id` (at `x, y`) to
    /// `parent` (at `px, py`), in order from the start; `tree` 0 on a path's first edge (a new
    /// search's path), 1 on the others. Lazy PRM checks it next (`EdgeChecked`).
    QueryPath = 24,
    /// EST picked node `id` of `tree` to grow by density: `x, y` its point; `px` the nodes in its
    /// grid cell; `py` the cell's probability (its 1/count over the sum for all cells); `c0` the
    /// cells in use; `c1, pc0` the cell's column and row; `pc1` the grid's cells a side.
    Select = 25,
    /// A graph edge was found (visibility graph): between vertices `id` (at `x, y`) and `parent`
    /// (at `px, py`); `c0` its length; `c1` 1 when the segment is clear (kept), 0 when blocked.
    GraphEdge = 26,
    /// The informed set shrank (Informed RRT*, after each better solution): the states that could
    /// still lie on a shorter path, `d(start, q) + d(q, goal) < c`, drawn in the plane as the
    /// ellipse with foci the start's and the goal's points: `x, y` its centre; `px, py` its
    /// semi-axes (major, minor); `c0, c1` the major axis's direction (unit); `pc0` the best cost
    /// `c`; `pc1` the distance between the foci. `id` the iteration. For robots whose states are
    /// not points of the plane the ellipse bounds the positions the set allows.
    Informed = 27,
}

impl EventKind {
    /// The set-up kinds: what a planner lays out before (or between) its decisions, not a decision
    /// itself: a decomposition's or a grid's cells and their outlines, a region of influence, a
    /// potential field's heat map. The page shows a run of them as one step (one level of a
    /// decomposition, a grid's cells, one heat map), so stepping starts at the first decision and
    /// a replay's pace is set by the decisions.
    pub const SETUP: [EventKind; 4] = [EventKind::Cell, EventKind::CellShape, EventKind::Region, EventKind::Field];

    /// Whether this kind is a set-up kind ([`EventKind::SETUP`]).
    pub fn is_setup(self) -> bool {
        Self::SETUP.contains(&self)
    }

    /// Every kind with its name, for the JS constant check.
    pub const ALL: [(EventKind, &'static str); 28] = [
        (EventKind::Sample, "SAMPLE"),
        (EventKind::SampleRejected, "SAMPLE_REJECTED"),
        (EventKind::NodeAdded, "NODE_ADDED"),
        (EventKind::Collision, "COLLISION"),
        (EventKind::TreesConnected, "TREES_CONNECTED"),
        (EventKind::Solved, "SOLVED"),
        (EventKind::SampleTry, "SAMPLE_TRY"),
        (EventKind::Domain, "DOMAIN"),
        (EventKind::Exhausted, "EXHAUSTED"),
        (EventKind::Rewire, "REWIRE"),
        (EventKind::Cost, "COST"),
        (EventKind::Coverage, "COVERAGE"),
        (EventKind::PointSeen, "POINT_SEEN"),
        (EventKind::Cell, "CELL"),
        (EventKind::CellShape, "CELL_SHAPE"),
        (EventKind::CellState, "CELL_STATE"),
        (EventKind::Potential, "POTENTIAL"),
        (EventKind::Region, "REGION"),
        (EventKind::Field, "FIELD"),
        (EventKind::Minimum, "MINIMUM"),
        (EventKind::Nearest, "NEAREST"),
        (EventKind::Steer, "STEER"),
        (EventKind::RoadmapEdge, "ROADMAP_EDGE"),
        (EventKind::EdgeChecked, "EDGE_CHECKED"),
        (EventKind::QueryPath, "QUERY_PATH"),
        (EventKind::Select, "SELECT"),
        (EventKind::GraphEdge, "GRAPH_EDGE"),
        (EventKind::Informed, "INFORMED"),
    ];
}

/// The event log. Recording can be switched off for benchmarks.
#[derive(Clone, Debug, Default)]
pub struct EventLog {
    data: Vec<f64>,
    /// Whether events are recorded.
    pub enabled: bool,
    /// Records drained so far (the node log's record numbers count from the run's first).
    drained: usize,
    /// The node log: off (`None`), or every `NodeAdded` record's full states, for a view that needs
    /// more than the records carry (a spatial arm's tool in 3-D, `Session::drain_nodes`).
    nodes: Option<NodeLog>,
    /// The state log: off (`None`), or the full states of the records a growth step is explained
    /// by (`EventLog::STATE_KINDS`), for an explain panel whose robot has more than the two
    /// coordinates a record carries (a spatial arm's six joints, `Session::drain_states`).
    states: Option<StateLog>,
}

/// The full states of the records of [`EventLog::STATE_KINDS`], in order: per record of those
/// kinds exactly one entry `[record, kind, extra, q…, pq…]` (`record` numbered from the run's
/// first; `q`, `pq` the record's state and its parent's or target's, see
/// [`EventLog::STATE_KINDS`]; `extra` NaN, or for a last-free connect's `Steer` the state checks
/// its configurations took). Explaining only: nothing a planner reads.
#[derive(Clone, Debug, Default)]
pub struct StateLog {
    /// Numbers per state.
    pub dims: usize,
    /// The entries, flat.
    pub data: Vec<f64>,
}

impl StateLog {
    /// Numbers per entry.
    pub fn stride(&self) -> usize {
        3 + 2 * self.dims
    }
}

/// Every `NodeAdded` record's states: `[record, tree, id, parent, q…, parent's q…]` per node, where
/// `record` numbers the record from the run's first. Drawing only: nothing a planner reads.
#[derive(Clone, Debug, Default)]
pub struct NodeLog {
    /// Numbers per state.
    pub dims: usize,
    /// The entries, flat.
    pub data: Vec<f64>,
}

impl NodeLog {
    /// Numbers per entry.
    pub fn stride(&self) -> usize {
        4 + 2 * self.dims
    }
}

impl EventLog {
    /// A log that records (or not).
    pub fn new(enabled: bool) -> Self {
        EventLog { data: Vec::new(), enabled, drained: 0, nodes: None, states: None }
    }
    /// The kinds whose records get a state log entry: `Sample` and `SampleRejected` (the sample,
    /// twice), `Nearest` (the node's state, the target's), `Steer` (the farthest state tested, the
    /// node's), `Collision` (where the motion was found not free, the state it started from),
    /// `NodeAdded` (the node's, its parent's), `TreesConnected` (the meeting state, twice).
    pub const STATE_KINDS: [EventKind; 7] = [
        EventKind::Sample,
        EventKind::SampleRejected,
        EventKind::Nearest,
        EventKind::Steer,
        EventKind::Collision,
        EventKind::NodeAdded,
        EventKind::TreesConnected,
    ];
    /// Keep the state log of states of `dims` numbers from now on (`0`: not).
    pub fn log_states(&mut self, dims: usize) {
        self.states = (dims > 0).then(|| StateLog { dims, data: Vec::new() });
    }
    /// Keep the node log of states of `dims` numbers from now on (`0`: not).
    pub fn log_nodes(&mut self, dims: usize) {
        self.nodes = (dims > 0).then(|| NodeLog { dims, data: Vec::new() });
    }
    /// Take the node log's entries so far (empty when it is off).
    pub fn drain_nodes(&mut self) -> NodeLog {
        match &mut self.nodes {
            Some(n) => NodeLog { dims: n.dims, data: std::mem::take(&mut n.data) },
            None => NodeLog::default(),
        }
    }
    /// Take the state log's entries so far (empty when it is off).
    pub fn drain_states(&mut self) -> StateLog {
        match &mut self.states {
            Some(n) => StateLog { dims: n.dims, data: std::mem::take(&mut n.data) },
            None => StateLog::default(),
        }
    }
    /// The state log entry of the record about to be made (when `kind` is one of
    /// [`STATE_KINDS`](EventLog::STATE_KINDS)): `q`, `pq`, or NaN when they are not states of the
    /// log's size, so that every such record has exactly one entry, in order.
    fn log_state(&mut self, kind: EventKind, q: &[Real], pq: &[Real]) {
        let record = (self.drained + self.data.len() / STRIDE) as f64;
        if let Some(s) = &mut self.states {
            if Self::STATE_KINDS.contains(&kind) {
                s.data.extend_from_slice(&[record, kind as u8 as f64, f64::NAN]);
                if q.len() == s.dims && pq.len() == s.dims {
                    s.data.extend_from_slice(q);
                    s.data.extend_from_slice(pq);
                } else {
                    s.data.resize(s.data.len() + 2 * s.dims, f64::NAN);
                }
            }
        }
    }
    /// Give the last record, made by [`values`](EventLog::values) or [`mark`](EventLog::mark)
    /// (which carry no states), its states in the state log: `q`, `pq`, and `extra` (see
    /// [`StateLog`]). Nothing when the log is off, the last record has no entry, or the states
    /// are not of its size.
    pub fn attach(&mut self, q: &[Real], pq: &[Real], extra: f64) {
        if !self.enabled {
            return;
        }
        if let Some((e, dims)) = self.last_entry() {
            if q.len() == dims && pq.len() == dims {
                e[2] = extra;
                e[3..3 + dims].copy_from_slice(q);
                e[3 + dims..].copy_from_slice(pq);
            }
        }
    }
    /// The state log's last entry and the log's `dims`, when that entry is the last record's.
    fn last_entry(&mut self) -> Option<(&mut [f64], usize)> {
        let last = (self.drained + self.data.len() / STRIDE).checked_sub(1)? as f64;
        let s = self.states.as_mut()?;
        let (stride, dims) = (s.stride(), s.dims);
        let n = s.data.len() / stride;
        (n > 0 && s.data[(n - 1) * stride] == last).then(|| (&mut s.data[(n - 1) * stride..], dims))
    }
    /// Record one event: ids, workspace points of the state and its parent, and the first two
    /// coordinates of each state.
    #[allow(clippy::too_many_arguments)]
    #[inline]
    pub fn push(
        &mut self,
        kind: EventKind,
        tree: usize,
        id: i64,
        parent: i64,
        p: Vec2,
        pp: Vec2,
        q: &[Real],
        pq: &[Real],
    ) {
        if self.enabled {
            if let Some(n) = &mut self.nodes {
                if kind == EventKind::NodeAdded && q.len() == n.dims && pq.len() == n.dims {
                    let record = (self.drained + self.data.len() / STRIDE) as f64;
                    n.data.extend_from_slice(&[record, tree as f64, id as f64, parent as f64]);
                    n.data.extend_from_slice(q);
                    n.data.extend_from_slice(pq);
                }
            }
            self.log_state(kind, q, pq);
            let c = |s: &[Real], i: usize| s.get(i).copied().unwrap_or(0.0);
            self.data.extend_from_slice(&[
                kind as u8 as f64,
                tree as f64,
                id as f64,
                parent as f64,
                p.x,
                p.y,
                pp.x,
                pp.y,
                c(q, 0),
                c(q, 1),
                c(pq, 0),
                c(pq, 1),
            ]);
        }
    }
    /// Record an event at one state (drawn at `p`).
    #[inline]
    pub fn at(&mut self, kind: EventKind, tree: usize, p: Vec2, q: &[Real]) {
        self.push(kind, tree, -1, -1, p, p, q, q)
    }
    /// Record an event that carries values rather than a parent state:
    /// `[kind, tree, id, parent, x, y, a, b, 0, 0, 0, 0]` (see each [`EventKind`] for the meaning).
    #[allow(clippy::too_many_arguments)]
    #[inline]
    pub fn mark(&mut self, kind: EventKind, tree: usize, id: i64, parent: f64, p: Vec2, a: f64, b: f64) {
        if self.enabled {
            self.log_state(kind, &[], &[]);
            self.data.extend_from_slice(&[
                kind as u8 as f64,
                tree as f64,
                id as f64,
                parent,
                p.x,
                p.y,
                a,
                b,
                0.0,
                0.0,
                0.0,
                0.0,
            ]);
        }
    }
    /// Record an event of values: `[kind, tree, id, parent, v[0], ..., v[7]]` (see each
    /// [`EventKind`] for the meaning).
    #[inline]
    pub fn values(&mut self, kind: EventKind, tree: usize, id: i64, parent: i64, v: [f64; 8]) {
        if self.enabled {
            self.log_state(kind, &[], &[]);
            self.data.extend_from_slice(&[kind as u8 as f64, tree as f64, id as f64, parent as f64]);
            self.data.extend_from_slice(&v);
        }
    }
    /// Set the `extra` number of the last record's state log entry (see [`StateLog`]), if it has one.
    pub fn set_extra(&mut self, extra: f64) {
        if let Some((e, _)) = self.last_entry() {
            e[2] = extra;
        }
    }
    /// Number of records waiting.
    pub fn len(&self) -> usize {
        self.data.len() / STRIDE
    }
    /// Whether no record is waiting.
    pub fn is_empty(&self) -> bool {
        self.data.is_empty()
    }
    /// Forget the records after the first `events` (a suspended batch's, see [`crate::journal`]).
    pub fn truncate(&mut self, events: usize) {
        self.data.truncate(events * STRIDE);
        // The side logs' entries of the records dropped (they are the last ones).
        let end = (self.drained + events) as f64;
        if let Some(n) = &mut self.nodes {
            let stride = n.stride();
            drop_entries_from(&mut n.data, stride, end);
        }
        if let Some(s) = &mut self.states {
            let stride = s.stride();
            drop_entries_from(&mut s.data, stride, end);
        }
    }
    /// Take every waiting record, leaving the log empty.
    pub fn drain(&mut self) -> Vec<f64> {
        self.drained += self.data.len() / STRIDE;
        std::mem::take(&mut self.data)
    }
    /// The waiting records.
    pub fn records(&self) -> &[f64] {
        &self.data
    }
}

/// Drop a side log's last entries (each `stride` numbers, its record's number first) whose record
/// is `end` or later.
fn drop_entries_from(data: &mut Vec<f64>, stride: usize, end: f64) {
    let mut keep = data.len() / stride;
    while keep > 0 && data[(keep - 1) * stride] >= end {
        keep -= 1;
    }
    data.truncate(keep * stride);
}
