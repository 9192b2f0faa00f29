use super::*;

const SEVEN: &str =
    "7\n0.193301 0.238602 0.15 0.213602 0.125 0.170301 0.150 0.127 0.200 0.127 0.225 0.170301 0.225 0.220301\t\n\
0.893301 0.238602 0.85 0.213602 0.825 0.170301 0.850 0.127 0.900 0.127 0.925 0.170301 0.925 0.220301\n\
2\n0.25 0.0 0.35 0.0 0.35 0.3 0.35 0.3\n0.25 0.33 0.35 0.33 0.35 0.65 0.35 0.65\n";

#[test]
fn words_carry_their_columns() {
    assert_eq!(words("  3\t0.5  x"), vec![(3, "3"), (5, "0.5"), (10, "x")]);
    assert!(words(" \t ").is_empty());
}

#[test]
fn a_problem_file_becomes_the_course_scenario() {
    let sc = import_problem(SEVEN, "7ASV").unwrap();
    assert_eq!(sc.name, "7ASV");
    assert_eq!(sc.bounds, [0.0, 0.0, 1.0, 1.0]);
    assert_eq!(sc.start.len(), 14);
    assert_eq!(sc.goal.as_ref().unwrap()[0], 0.893301);
    // Corners (0.25,0) (0.35,0) (0.35,0.3) (0.35,0.3): the box of the four.
    assert_eq!(
        sc.obstacles,
        vec![ObstacleSpec::Rect([0.25, 0.0, 0.35, 0.3]), ObstacleSpec::Rect([0.25, 0.33, 0.35, 0.65])]
    );
    match sc.robot {
        RobotSpec::Asv { count, broom, min_area, convex, max_step } => {
            assert_eq!((count, broom, convex, max_step), (7, 0.05, true, 0.001));
            assert!((min_area - std::f64::consts::PI * 0.042f64.powi(2)).abs() < 1e-15);
        }
        _ => panic!("not an asv robot"),
    }
    assert!(sc.touching_allowed && sc.resolution == 0.001);
    assert_eq!(sc.planner.as_ref().unwrap().name, "rrt-connect");
    // It is a valid scenario: it round-trips through the contract and builds a problem.
    let again = Scenario::from_json(&sc.to_json()).unwrap();
    assert_eq!(again, sc);
    crate::problem::Problem::from_scenario(&sc).unwrap();
}

#[test]
fn problem_errors_point_at_the_word() {
    let e = import_problem("3\n0.1 0.2 0.3 oops 0.5 0.6\n", "x").unwrap_err();
    assert_eq!((e.line, e.column), (Some(2), Some(13)));
    assert!(
        e.to_string().starts_with("line 2, column 13: the initial positions: expected a number, found \"oops\""),
        "{e}"
    );
    let e = import_problem("3\n", "x").unwrap_err();
    assert_eq!(e.line, Some(2));
    assert!(e.message.contains("end of the file"), "{e}");
    let e = import_problem("2\n", "x").unwrap_err();
    assert!(e.message.contains("3 or more"), "{e}");
}

#[test]
fn solution_files_read_back() {
    let text = "2 0.002\n0 0 0.05 0\n0.001 0 0.051 0\n\n0.002 0 0.052 0\n";
    let c = read_solution(text).unwrap();
    assert_eq!(c.len(), 3);
    assert_eq!(c[2], vec![0.002, 0.0, 0.052, 0.0]);
    assert!((path_cost(&c) - 0.004).abs() < 1e-15);
    assert!((max_move(&c[0], &c[1]) - 0.001).abs() < 1e-15);
    let short = read_solution("3 0\n0 0 0.05 0\n").unwrap_err();
    assert!(short.starts_with("line 3"), "{short}");
    let long = read_solution("0 0\n0 0 0.05 0\n1 1 1 1\n").unwrap_err();
    assert!(long.starts_with("line 3") && long.contains("more configurations"), "{long}");
    let odd = read_solution("0 0\n0 0 0.05\n").unwrap_err();
    assert!(odd.contains("x y pairs"), "{odd}");
}
