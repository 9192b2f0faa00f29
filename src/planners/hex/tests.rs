use super::cells::*;
use crate::geometry::convex::{convex_contains, hexagon, share_edge};
use crate::geometry::{Aabb, Shape, Workspace};
use crate::math::{Real, Vec2};

fn area(ring: &[Vec2]) -> Real {
    let n = ring.len();
    (0..n).map(|i| ring[i].perp(&ring[(i + 1) % n])).sum::<Real>() / 2.0
}

fn unit() -> Aabb {
    Aabb { min: Vec2::new(0.0, 0.0), max: Vec2::new(1.0, 0.8) }
}

#[test]
fn the_coarse_tiling_covers_the_map_exactly() {
    let d = Decomposition::tiling(&unit(), 0.1);
    let total: Real = d.cells.iter().map(|c| area(&c.outline)).sum();
    assert!((total - 0.8).abs() < 1e-9, "tiling area {total}");
    // Half hexagons along the bottom edge: cells centred on y = 0 keep half their area.
    let full = 1.5 * 3f64.sqrt() * 0.01;
    assert!(d.cells.iter().any(|c| (area(&c.outline) - full / 2.0).abs() < 1e-9), "some half hexagons at the border");
    assert!(d.cells.iter().all(|c| area(&c.outline) > 0.0 && c.outline.len() >= 3));
}

#[test]
fn a_hexagon_splits_exactly_into_a_hexagon_and_six_half_hexagons() {
    let mut d = Decomposition::tiling(&Aabb { min: Vec2::new(-1.0, -1.0), max: Vec2::new(1.0, 1.0) }, 0.4);
    let i = d.cells.iter().position(|c| c.outline.len() == 6).expect("an unclipped hexagon");
    let parent_area = area(&d.cells[i].outline);
    let kids = d.refine(i);
    assert_eq!(kids.len(), 7);
    let areas: Vec<Real> = kids.clone().map(|k| area(&d.cells[k].outline)).collect();
    let sum: Real = areas.iter().sum();
    assert!((sum - parent_area).abs() < 1e-12, "children {sum} vs parent {parent_area}");
    // One whole hexagon of a quarter the area, six halves of it.
    let quarter = parent_area / 4.0;
    assert!((areas[0] - quarter).abs() < 1e-12);
    assert!(areas[1..].iter().all(|a| (a - quarter / 2.0).abs() < 1e-12), "{areas:?}");
    // Refining a half hexagon again still partitions it.
    let half = kids.start + 1;
    let half_area = area(&d.cells[half].outline);
    let grand = d.refine(half);
    let sum: Real = grand.map(|k| area(&d.cells[k].outline)).sum();
    assert!((sum - half_area).abs() < 1e-12);
}

#[test]
fn cells_are_labelled_free_mixed_or_full() {
    let ws = Workspace::new(
        Aabb { min: Vec2::new(0.0, 0.0), max: Vec2::new(1.0, 1.0) },
        vec![Shape::Rect(Aabb { min: Vec2::new(0.3, 0.3), max: Vec2::new(0.7, 0.7) })],
    );
    let hex = |c: Vec2, s: Real| hexagon(c, s).to_vec();
    let lab = |o: Vec<Vec2>| label_of(&ws, &o, &Aabb::of_points(&o));
    assert_eq!(lab(hex(Vec2::new(0.5, 0.5), 0.1)), CellLabel::Full);
    assert_eq!(lab(hex(Vec2::new(0.3, 0.5), 0.1)), CellLabel::Mixed);
    assert_eq!(lab(hex(Vec2::new(0.1, 0.1), 0.05)), CellLabel::Free);
}

#[test]
fn neighbours_share_an_edge_across_levels() {
    let mut d = Decomposition::tiling(&unit(), 0.2);
    let i = d.leaf_at(Vec2::new(0.5, 0.4)).expect("a cell");
    let kids: Vec<usize> = d.refine(i).collect();
    let leaves: Vec<usize> = (0..d.cells.len()).filter(|&k| d.cells[k].is_leaf()).collect();
    let adj = d.adjacency(&leaves);
    let pos = |c: usize| leaves.iter().position(|&l| l == c).expect("a leaf");
    // Symmetric.
    for (a, list) in adj.iter().enumerate() {
        for &b in list {
            assert!(adj[b].contains(&a), "{a} → {b} but not back");
        }
    }
    // The centre child touches its six half-hexagon siblings and nothing else.
    let centre = pos(kids[0]);
    let mut got: Vec<usize> = adj[centre].iter().map(|&k| leaves[k]).collect();
    got.sort_unstable();
    assert_eq!(got, kids[1..].to_vec());
    // Every coarse neighbour of the refined cell touches some child.
    for &n in &leaves {
        if d.cells[n].level == 0 && share_edge(&d.cells[n].outline, &d.cells[i].outline) {
            assert!(adj[pos(n)].iter().any(|&k| kids.contains(&leaves[k])), "coarse cell {n} touches no child");
        }
    }
    // Corner-touching cells are not neighbours.
    assert!(!share_edge(
        &hexagon(Vec2::new(0.0, 0.0), 1.0),
        &[Vec2::new(0.866, 0.5), Vec2::new(2.0, 0.0), Vec2::new(2.0, 1.0)]
    ));
}

#[test]
fn the_leaf_at_a_point_contains_it() {
    let mut d = Decomposition::tiling(&unit(), 0.2);
    let p = Vec2::new(0.41, 0.37);
    let i = d.leaf_at(p).expect("a cell");
    d.refine(i);
    let j = d.leaf_at(p).expect("a leaf");
    assert_eq!(d.cells[j].parent, Some(i));
    assert!(convex_contains(&d.cells[j].outline, p));
}
