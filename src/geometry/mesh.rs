//! Triangle meshes of the 3-D solids, for drawing only (the page's 3-D view): a hull's faces from
//! parry3d's convex hull of its vertices, a box's 12 triangles. Every triangle is wound
//! counter-clockwise seen from outside (its normal `(b − a) × (c − a)` points away from the
//! solid's interior). Built once per scenario; no query uses them.

use super::solid::{Convex, Solid};
use crate::math::Real;
use parry3d_f64::math::Vector;

/// A triangle mesh: vertices and triangles as indices into them.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// The vertices.
    pub vertices: Vec<[Real; 3]>,
    /// The triangles, counter-clockwise seen from outside.
    pub triangles: Vec<[u32; 3]>,
}

fn sub(a: [Real; 3], b: [Real; 3]) -> [Real; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross(a: [Real; 3], b: [Real; 3]) -> [Real; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn dot(a: [Real; 3], b: [Real; 3]) -> Real {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

impl Mesh {
    /// The mesh of a solid in its own frame (a box placed at its centre).
    pub fn of_solid(s: &Solid) -> Mesh {
        match &s.convex {
            Convex::Cuboid(_) => Mesh::of_box(s.bounds.lo, s.bounds.hi),
            Convex::Hull(h) => {
                let pts: Vec<Vector> = h.poly.points().to_vec();
                match parry3d_f64::transformation::try_convex_hull(&pts) {
                    Ok((vs, ts)) => {
                        Mesh { vertices: vs.iter().map(|v| [v.x, v.y, v.z]).collect(), triangles: ts }.outwards()
                    }
                    // The solid was built from the same points, so this cannot happen; drawn as its box.
                    Err(_) => Mesh::of_box(s.bounds.lo, s.bounds.hi),
                }
            }
        }
    }

    /// The box `lo ..= hi`: 8 corners (corner `i` takes `hi` on axis `k` when bit `k` of `i` is
    /// set) and 12 triangles.
    pub fn of_box(lo: [Real; 3], hi: [Real; 3]) -> Mesh {
        let vertices = (0..8).map(|i| [0, 1, 2].map(|k| if i & (1 << k) != 0 { hi[k] } else { lo[k] })).collect();
        // Each face's four corners in order around it.
        const FACES: [[u32; 4]; 6] =
            [[0, 2, 6, 4], [1, 5, 7, 3], [0, 4, 5, 1], [2, 3, 7, 6], [0, 1, 3, 2], [4, 6, 7, 5]];
        let triangles = FACES.iter().flat_map(|[a, b, c, d]| [[*a, *b, *c], [*a, *c, *d]]).collect();
        Mesh { vertices, triangles }.outwards()
    }

    /// The vertices' mean: inside a convex solid (for the winding).
    pub fn centroid(&self) -> [Real; 3] {
        let n = self.vertices.len().max(1) as Real;
        let mut c = [0.0; 3];
        for v in &self.vertices {
            for k in 0..3 {
                c[k] += v[k] / n;
            }
        }
        c
    }

    /// Triangle `t`'s normal `(b − a) × (c − a)` (not normalised).
    pub fn normal(&self, t: [u32; 3]) -> [Real; 3] {
        let [a, b, c] = t.map(|i| self.vertices[i as usize]);
        cross(sub(b, a), sub(c, a))
    }

    /// The same mesh with every triangle wound to face away from the centroid (a convex solid's
    /// outside).
    fn outwards(mut self) -> Mesh {
        let c = self.centroid();
        for i in 0..self.triangles.len() {
            let t = self.triangles[i];
            if dot(self.normal(t), sub(self.vertices[t[0] as usize], c)) < 0.0 {
                self.triangles[i] = [t[0], t[2], t[1]];
            }
        }
        self
    }

    /// As JSON `{vertices: [x, y, z, …], triangles: [i, j, k, …]}` (flat).
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({
            "vertices": self.vertices.concat(),
            "triangles": self.triangles.concat(),
        })
    }
}
