//! What the page may do with a loaded scenario, decided here rather than by the page from kind
//! names: the robot kind's record ([`crate::robot::kinds`]), whether a configuration-space view is
//! drawn, whether the optimum (the visibility graph's shortest path, the cost chart's reference
//! line) is computed, whether a solved run's solution file can be downloaded, and what of a start
//! or goal may be dragged. The worker sends it with its `loaded` reply (`wasm::Scene::caps_json`).

use crate::problem::Problem;
use crate::robot::kinds::{Pose, RobotKind};

/// A loaded scenario's capabilities.
#[derive(Clone, Copy, Debug)]
pub struct SceneCaps {
    /// The robot kind's record.
    pub robot: &'static RobotKind,
    /// A configuration-space view: a two-dimensional space of joint angles.
    pub cspace: bool,
    /// The optimum is computed: a goal, a robot whose paths are polylines in the plane, and at most
    /// the given obstacles (the graph is quadratic in its corners).
    pub optimum: bool,
    /// A solved run's path can be downloaded as the course's solution file.
    pub solution_file: bool,
    /// What of a start or goal may be dragged.
    pub pose: Pose,
    /// A 3-D view: the robot has the [`Spatial`](crate::robot::Spatial) capability (its parts'
    /// meshes and link frames, `wasm::Scene::spatial_json` and `link_frames`).
    pub view3d: bool,
}

impl SceneCaps {
    /// The capabilities of `p`; the optimum on at most `optimum_max_obstacles` obstacles.
    pub fn of(p: &Problem, optimum_max_obstacles: usize) -> SceneCaps {
        let robot = p.robot.caps();
        SceneCaps {
            robot,
            cspace: robot.cspace && p.si.dims() == 2,
            optimum: p.goal.is_some() && robot.body && p.scenario.obstacles.len() <= optimum_max_obstacles,
            solution_file: robot.solution_file,
            pose: robot.pose,
            view3d: p.robot.spatial().is_some(),
        }
    }
    /// As JSON `{robot: {…the kind's record}, cspace, optimum, solution_file, pose, view3d}`.
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({
            "robot": self.robot.to_json(), "cspace": self.cspace, "optimum": self.optimum,
            "solution_file": self.solution_file, "pose": self.pose.as_str(), "view3d": self.view3d,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::builtin;

    fn caps(id: &str, max: usize) -> SceneCaps {
        SceneCaps::of(&Problem::from_scenario(&builtin(id).unwrap()).unwrap(), max)
    }

    /// What the page decided by kind names before, now decided here, for the built-ins.
    #[test]
    fn decided_by_the_robot_and_the_scenario() {
        for (id, _) in crate::scenario::BUILTINS {
            let sc = builtin(id).unwrap();
            let c = caps(id, 500);
            let kind = c.robot.name;
            let dims = Problem::from_scenario(&sc).unwrap().si.dims();
            assert_eq!(c.cspace, kind == "arm" && dims == 2, "{id}");
            assert_eq!(
                c.optimum,
                sc.goal.is_some() && (kind == "point" || kind == "rigid") && sc.obstacles.len() <= 500,
                "{id}"
            );
            assert_eq!(c.solution_file, kind == "asv", "{id}");
            assert_eq!(c.view3d, kind == "spatial-arm", "{id}");
        }
        assert!(!caps("narrow", 0).optimum, "the obstacle bound holds");
        assert!(caps("arm-2", 500).cspace && !caps("arm-3", 500).cspace);
    }
}
