//! Occupancy maps (issue 17): map_server's PGM + YAML and a PNG of the same map import to the same
//! scenario; export then import gives the same grid; thresholds, negate, unknown pixels, the top
//! row's orientation, P2 against P5, 16-bit and colour PNGs; malformed inputs give named errors and
//! never panic; grid-search labels exactly the image's occupied pixels blocked; grid-search and
//! rrt-connect solve an imported map with paths the independent checker accepts.

mod common;

use planarium::events::{EventKind, STRIDE};
use planarium::io::occupancy::{self, Occupancy, OccupancyGrid};
use planarium::planners::{self, Params};
use planarium::problem::Problem;
use planarium::run::{PlanResult, RunConfig, Session};
use planarium::scenario::{Scenario, ScenarioError};
use serde_json::{json, Value};

const DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/maps");

fn read(name: &str) -> Vec<u8> {
    std::fs::read(format!("{DIR}/{name}")).unwrap()
}

fn text(name: &str) -> String {
    String::from_utf8(read(name)).unwrap()
}

/// The map of `yaml` (its image read beside it).
fn import_yaml(yaml: &str) -> Scenario {
    let t = text(yaml);
    let meta = occupancy::parse_yaml(&t, yaml).unwrap();
    occupancy::import_image(&read(&meta.image), &meta.image, Some((&t, yaml))).unwrap()
}

/// The sample's grid as its YAML reads it.
fn sample_grid() -> OccupancyGrid {
    let meta = occupancy::parse_yaml(&text("sample.yaml"), "sample.yaml").unwrap();
    occupancy::classify(&occupancy::decode_image(&read("sample.pgm"), "sample.pgm").unwrap(), &meta)
}

/// Everything but the title.
fn same_map(a: &Scenario, b: &Scenario) {
    assert_eq!(a.bounds, b.bounds);
    assert_eq!(a.obstacles, b.obstacles);
    assert_eq!(a.start, b.start);
    assert_eq!(a.goal, b.goal);
    assert_eq!(a.map, b.map);
    assert_eq!(a.resolution, b.resolution);
}

fn grey_image(w: usize, h: usize, values: &[u16], maxval: u16) -> occupancy::Image {
    occupancy::Image { width: w, height: h, maxval, values: values.to_vec() }
}

fn p5(w: usize, h: usize, maxval: u16, values: &[u16]) -> Vec<u8> {
    let mut out = format!("P5\n# a comment\n{w} {h}\n{maxval}\n").into_bytes();
    for &v in values {
        if maxval < 256 {
            out.push(v as u8);
        } else {
            out.extend_from_slice(&v.to_be_bytes());
        }
    }
    out
}

fn p2(w: usize, h: usize, maxval: u16, values: &[u16]) -> Vec<u8> {
    let body: Vec<String> = values.iter().map(|v| v.to_string()).collect();
    format!("P2 {w} # width\n{h}\n{maxval}\n{}\n", body.join(" ")).into_bytes()
}

fn png_of(w: u32, h: u32, color: png::ColorType, depth: png::BitDepth, data: &[u8], palette: Option<&[u8]>) -> Vec<u8> {
    let mut out = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut out, w, h);
        enc.set_color(color);
        enc.set_depth(depth);
        if let Some(p) = palette {
            enc.set_palette(p.to_vec());
        }
        let mut wr = enc.write_header().unwrap();
        wr.write_image_data(data).unwrap();
    }
    out
}

fn plain(bytes: &[u8], name: &str) -> Result<OccupancyGrid, ScenarioError> {
    let img = occupancy::decode_image(bytes, name)?;
    Ok(occupancy::classify(&img, &occupancy::MapMeta::plain(name)))
}

#[test]
fn a_map_server_pgm_with_its_yaml_and_a_png_of_the_same_map_import_to_the_same_scenario() {
    let from_pgm = import_yaml("sample.yaml");
    let from_png = import_yaml("sample-png.yaml");
    same_map(&from_pgm, &from_png);
    // The pixels' grids too, and the plain images (no YAML) agree with each other.
    assert_eq!(plain(&read("sample.pgm"), "a").unwrap().cells, plain(&read("sample.png"), "a").unwrap().cells);
    assert_eq!(sample_grid().cells, plain(&read("sample.png"), "a").unwrap().cells);
    // The sample: 6 rectangles (two walls, an L of two, the unknown patch, a lone pixel).
    assert_eq!(from_pgm.obstacles.len(), 6, "{:?}", from_pgm.obstacles);
    assert_eq!(from_pgm.bounds, [-1.0, -0.5, -1.0 + 40.0 * 0.1, -0.5 + 30.0 * 0.1]);
    let m = from_pgm.map.as_ref().unwrap();
    assert_eq!((m.resolution, m.origin), (0.1, [-1.0, -0.5]));
    // The map block round-trips through the scenario's JSON.
    let again = Scenario::from_json(&from_pgm.to_json()).unwrap();
    assert_eq!(again, from_pgm);
}

#[test]
fn export_then_import_gives_the_same_grid() {
    let sc = import_yaml("sample.yaml");
    let grid = occupancy::scenario_to_grid(&sc, 0.1).unwrap();
    // Unknown pixels plan (and so export) as occupied.
    assert_eq!(grid.blocked_mask(), sample_grid().blocked_mask());
    assert_eq!((grid.width, grid.height, grid.origin), (40, 30, [-1.0, -0.5]));
    let (pgm, yaml) = occupancy::to_pgm_yaml(&grid, "out.pgm");
    assert!(yaml.contains("image: out.pgm\n"), "{yaml}");
    let back = occupancy::import_image(&pgm, "out.pgm", Some((&yaml, "out.yaml"))).unwrap();
    let meta = occupancy::parse_yaml(&yaml, "out.yaml").unwrap();
    let grid2 = occupancy::classify(&occupancy::decode_image(&pgm, "out.pgm").unwrap(), &meta);
    assert_eq!(grid2, grid);
    let grid3 = occupancy::classify(&occupancy::decode_image(&occupancy::to_png(&grid), "out.png").unwrap(), &meta);
    assert_eq!(grid3, grid);
    // The re-imported scenario has the same rectangles as the first (only the unknown patch's
    // pixels are now occupied ones: same boxes).
    assert_eq!(back.obstacles, sc.obstacles);
    assert_eq!(back.bounds, sc.bounds);
    // A built-in scenario exported at a cell and imported back rasterises to the same grid.
    let narrow = planarium::scenario::builtin("zigzag").unwrap();
    let g = occupancy::scenario_to_grid(&narrow, 0.02).unwrap();
    let (pgm, yaml) = occupancy::to_pgm_yaml(&g, "z.pgm");
    let z = occupancy::import_image(&pgm, "z.pgm", Some((&yaml, "z.yaml"))).unwrap();
    assert_eq!(occupancy::scenario_to_grid(&z, 0.02).unwrap(), g);
}

#[test]
fn the_top_row_of_the_image_is_the_top_of_the_map() {
    // 3×2, only the top left pixel dark.
    let img = grey_image(3, 2, &[0, 255, 255, 255, 255, 255], 255);
    let mut meta = occupancy::MapMeta::plain("t");
    meta.resolution = 0.5;
    meta.origin = [10.0, 20.0];
    let grid = occupancy::classify(&img, &meta);
    assert_eq!(occupancy::rectangles(&grid), vec![[10.0, 20.5, 10.5, 21.0]]);
    let sc = occupancy::grid_to_scenario(&grid, "t").unwrap();
    // Start: the free pixel nearest the lower left corner (its centre); goal: nearest the upper right.
    assert_eq!(sc.start, vec![10.25, 20.25]);
    assert_eq!(sc.goal, Some(vec![11.25, 20.75]));
}

#[test]
fn thresholds_negate_and_unknown_pixels_follow_map_server() {
    // 0 (black), 128 (p = 0.498), 60 (p = 0.765), 230 (p = 0.098), 255 (white)
    let img = grey_image(5, 1, &[0, 128, 60, 230, 255], 255);
    use Occupancy::*;
    let mut meta = occupancy::MapMeta::plain("t");
    assert_eq!(occupancy::classify(&img, &meta).cells, vec![Occupied, Unknown, Occupied, Free, Free]);
    meta.occupied_thresh = 0.4;
    assert_eq!(occupancy::classify(&img, &meta).cells, vec![Occupied, Occupied, Occupied, Free, Free]);
    meta.occupied_thresh = 0.9;
    meta.free_thresh = 0.6;
    assert_eq!(occupancy::classify(&img, &meta).cells, vec![Occupied, Free, Unknown, Free, Free]);
    let mut meta = occupancy::MapMeta::plain("t");
    meta.negate = true;
    assert_eq!(occupancy::classify(&img, &meta).cells, vec![Free, Unknown, Unknown, Occupied, Occupied]); // 60: p = 0.235
                                                                                                          // The thresholds and negate as a YAML gives them.
    let y = "image: t.pgm\nresolution: 1\norigin: [0, 0, 0]\nnegate: 1\noccupied_thresh: 0.9\nfree_thresh: 0.05 # comment\n";
    let m = occupancy::parse_yaml(y, "t.yaml").unwrap();
    assert!(m.negate);
    assert_eq!((m.occupied_thresh, m.free_thresh), (0.9, 0.05));
    // Unknown pixels become obstacles, and the scenario's notes say so.
    let mut meta = occupancy::MapMeta::plain("t");
    meta.resolution = 1.0;
    let img = grey_image(4, 1, &[255, 128, 255, 255], 255);
    let sc = occupancy::grid_to_scenario(&occupancy::classify(&img, &meta), "t").unwrap();
    assert_eq!(sc.obstacles.len(), 1);
    assert!(sc.notes.contains("1 unknown ones, which planning treats as occupied"), "{}", sc.notes);
    // raw mode: the value is the occupancy in percent.
    let mut meta = occupancy::MapMeta::plain("t");
    meta.mode = "raw".into();
    let img = grey_image(3, 1, &[0, 100, 255], 255);
    assert_eq!(occupancy::classify(&img, &meta).cells, vec![Free, Occupied, Unknown]);
}

#[test]
fn p2_p5_sixteen_bit_and_every_png_colour_type_read_the_same() {
    let vals8: Vec<u16> = vec![0, 254, 205, 254, 0, 10, 250, 128];
    let want = plain(&p5(4, 2, 255, &vals8), "a.pgm").unwrap();
    assert_eq!(plain(&p2(4, 2, 255, &vals8), "a.pgm").unwrap(), want);
    let vals16: Vec<u16> = vals8.iter().map(|v| v * 257).collect();
    assert_eq!(plain(&p5(4, 2, 65535, &vals16), "a.pgm").unwrap(), want);
    assert_eq!(plain(&p2(4, 2, 65535, &vals16), "a.pgm").unwrap(), want);
    let bytes8: Vec<u8> = vals8.iter().map(|v| *v as u8).collect();
    use png::{BitDepth, ColorType};
    let grey = png_of(4, 2, ColorType::Grayscale, BitDepth::Eight, &bytes8, None);
    assert_eq!(plain(&grey, "a.png").unwrap(), want);
    let g16: Vec<u8> = vals16.iter().flat_map(|v| v.to_be_bytes()).collect();
    assert_eq!(plain(&png_of(4, 2, ColorType::Grayscale, BitDepth::Sixteen, &g16, None), "a.png").unwrap(), want);
    let ga: Vec<u8> = bytes8.iter().flat_map(|v| [*v, 255]).collect();
    assert_eq!(plain(&png_of(4, 2, ColorType::GrayscaleAlpha, BitDepth::Eight, &ga, None), "a.png").unwrap(), want);
    let rgb: Vec<u8> = bytes8.iter().flat_map(|v| [*v, *v, *v]).collect();
    assert_eq!(plain(&png_of(4, 2, ColorType::Rgb, BitDepth::Eight, &rgb, None), "a.png").unwrap(), want);
    let rgba: Vec<u8> = bytes8.iter().flat_map(|v| [*v, *v, *v, 200]).collect();
    assert_eq!(plain(&png_of(4, 2, ColorType::Rgba, BitDepth::Eight, &rgba, None), "a.png").unwrap(), want);
    // A palette of the distinct greys.
    let mut pal: Vec<u8> = Vec::new();
    let mut idx = Vec::new();
    for v in &bytes8 {
        let at = pal.chunks(3).position(|c| c[0] == *v).unwrap_or_else(|| {
            pal.extend_from_slice(&[*v, *v, *v]);
            pal.len() / 3 - 1
        });
        idx.push(at as u8);
    }
    assert_eq!(plain(&png_of(4, 2, ColorType::Indexed, BitDepth::Eight, &idx, Some(&pal)), "a.png").unwrap(), want);
    // Colour: the mean of the channels (map_server's rule): pure red is 85, occupied.
    let red = png_of(1, 1, ColorType::Rgb, BitDepth::Eight, &[255, 0, 0], None);
    assert_eq!(plain(&red, "r.png").unwrap().cells, vec![Occupancy::Occupied]);
    // 1-bit grey expands: 0 occupied, 1 free.
    let bits = png_of(8, 1, ColorType::Grayscale, BitDepth::One, &[0b1010_0000], None);
    use Occupancy::*;
    assert_eq!(
        plain(&bits, "b.png").unwrap().cells,
        vec![Free, Occupied, Free, Occupied, Occupied, Occupied, Occupied, Occupied]
    );
}

fn err_of(r: Result<impl std::fmt::Debug, ScenarioError>) -> String {
    r.expect_err("should be refused").to_string()
}

#[test]
fn malformed_inputs_give_named_errors() {
    let good = p5(4, 2, 255, &[0; 8]);
    let e = err_of(occupancy::decode_image(&good[..good.len() - 3], "m.pgm"));
    assert!(
        e.starts_with("m.pgm: byte ") && e.contains("truncated: 4×2 pixels need 8 bytes of pixels, the file has 5"),
        "{e}"
    );
    let e = err_of(occupancy::decode_image(b"P5\n4 ", "m.pgm"));
    assert!(e.contains("the file ends where the height should be (truncated)"), "{e}");
    let e = err_of(occupancy::decode_image(b"GIF89a....", "m.gif"));
    assert!(e.starts_with("m.gif: not a map image"), "{e}");
    let e = err_of(occupancy::decode_image(b"P5x 4 2 255\n", "m.pgm"));
    assert!(e.contains("bad magic"), "{e}");
    let e = err_of(occupancy::decode_image(b"P5\n100000 100000\n255\n", "big.pgm"));
    assert!(e.contains("the image is 100000×100000 pixels; the limits are 4096 pixels a side"), "{e}");
    let e = err_of(occupancy::decode_image(b"P5\n99999999999999999999999 2\n255\n", "big.pgm"));
    assert!(e.contains("the width") && e.contains("is above"), "{e}");
    let e = err_of(occupancy::decode_image(b"P5\n4000 4000\n255\n", "big.pgm"));
    assert!(e.contains("4000000 pixels in all"), "{e}");
    let e = err_of(occupancy::decode_image(b"P2\n2 1\n255\n0 300\n", "v.pgm"));
    assert!(e.contains("the value of pixel 1 300 is above 255"), "{e}");
    let e = err_of(occupancy::decode_image(b"P5\n2 1\n0\n\0\0", "v.pgm"));
    assert!(e.contains("maxval must be 1 to 65535"), "{e}");
    // A PNG whose header says 5000 pixels wide: refused before its pixels are read.
    let wide = png_of(5000, 1, png::ColorType::Grayscale, png::BitDepth::Eight, &[0; 5000], None);
    let e = err_of(occupancy::decode_image(&wide, "w.png"));
    assert!(e.contains("w.png: the image is 5000×1 pixels"), "{e}");
    let png8 = png_of(4, 2, png::ColorType::Grayscale, png::BitDepth::Eight, &[0; 8], None);
    let e = err_of(occupancy::decode_image(&png8[..40], "t.png"));
    assert!(e.starts_with("t.png: not a readable PNG"), "{e}");
    // YAML: a missing key, a bad number (line and column), a yaw, an unknown key, a bad mode.
    let e = err_of(occupancy::parse_yaml("image: a.pgm\norigin: [0, 0, 0]\n", "m.yaml"));
    assert!(e.contains("m.yaml: resolution: is missing"), "{e}");
    let e = err_of(occupancy::parse_yaml("image: a.pgm\n\nresolution: 0.o5\n", "m.yaml"));
    assert_eq!(e, "line 3, column 13: m.yaml: resolution: \"0.o5\" is not a number");
    let e = err_of(occupancy::parse_yaml("image: a.pgm\nresolution: 1\norigin: [0.0,  x, 0]\n", "m.yaml"));
    assert_eq!(e, "line 3, column 16: m.yaml: origin: \"x\" is not a number");
    let e = err_of(occupancy::parse_yaml("image: a.pgm\nresolution: 1\norigin: [0, 0, 1.57]\n", "m.yaml"));
    assert!(e.contains("a yaw of 1.57 is not supported"), "{e}");
    let e = err_of(occupancy::parse_yaml("image: a.pgm\nresolutoin: 1\n", "m.yaml"));
    assert!(e.starts_with("line 2, column 1: m.yaml: resolutoin: unknown key"), "{e}");
    let e = err_of(occupancy::parse_yaml("image: a.pgm\nresolution: 1\nmode: fancy\n", "m.yaml"));
    assert!(e.contains("mode: \"fancy\" is not a mode"), "{e}");
    let e = err_of(occupancy::parse_yaml("image: a.pgm\nresolution: -1\n", "m.yaml"));
    assert!(e.contains("resolution: must be positive"), "{e}");
    let e = err_of(occupancy::parse_yaml("image: a.pgm\nresolution: 1\nresolution: 2\n", "m.yaml"));
    assert!(e.contains("appears twice"), "{e}");
    // A map with no free pixel, and a scenario's map block with a bad resolution.
    let e = err_of(occupancy::import_image(&p5(2, 2, 255, &[0; 4]), "black.pgm", None));
    assert!(e.contains("black.pgm: the map has no free pixel"), "{e}");
    let mut v: Value = serde_json::from_str(&import_yaml("sample.yaml").to_json()).unwrap();
    v["map"]["resolution"] = json!(0);
    assert_eq!(err_of(Scenario::from_value(&v)), "map.resolution: must be positive");
    v["map"] = json!({"resolution": 1, "origin": [0, 0], "yaw": 0});
    assert!(err_of(Scenario::from_value(&v)).starts_with("map.yaw: unknown key"));
}

#[test]
fn no_input_makes_the_readers_panic() {
    // Every prefix and many byte mutations of the sample files (deterministic).
    let files = [read("sample.pgm"), read("sample.png"), p5(4, 2, 65535, &[1; 8]), read("sample.yaml")];
    let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut next = || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        x
    };
    let yaml = text("sample.yaml");
    for f in &files {
        for n in 0..f.len().min(400) {
            let _ = occupancy::import_image(&f[..n], "p", None);
            let _ = occupancy::parse_yaml(&String::from_utf8_lossy(&f[..n]), "p");
        }
        for _ in 0..2000 {
            let mut g = f.clone();
            for _ in 0..1 + next() % 4 {
                let i = (next() as usize) % g.len();
                g[i] = next() as u8;
            }
            let _ = occupancy::import_image(&g, "p", Some((&yaml, "y")));
            let _ = occupancy::import_image(&g, "p", None);
            let _ = occupancy::parse_yaml(&String::from_utf8_lossy(&g), "p");
        }
    }
}

/// A run of `planner` on `sc`, with its events.
fn run(sc: &Scenario, planner: &str, params: Value) -> (PlanResult, Vec<f64>) {
    let spec = planners::find(planner).unwrap();
    let p = Params::from_json(spec, &params).unwrap();
    let problem = Problem::from_scenario(sc).unwrap();
    let mut s =
        Session::new(problem, RunConfig { planner: planner.into(), params: p, seed: 1, record_events: true }).unwrap();
    s.run_to_end();
    let ev = s.drain_events();
    (s.result(), ev)
}

#[test]
fn grid_search_labels_exactly_the_images_occupied_pixels_blocked() {
    let sc = import_yaml("sample.yaml");
    let grid = sample_grid();
    let (r, ev) = run(&sc, "grid-search", json!({}));
    assert!(r.solved);
    let mut blocked = vec![None; grid.width * grid.height];
    for rec in ev.chunks(STRIDE).filter(|r| r[0] as u8 == EventKind::Cell as u8) {
        let k = rec[2] as usize;
        let (i, j) = (k % grid.width, k / grid.width);
        // The planner's rows count from the bottom, the image's from the top.
        let row = grid.height - 1 - j;
        blocked[row * grid.width + i] = Some(rec[6] == 2.0);
    }
    let labelled: Vec<bool> = blocked.iter().map(|b| b.expect("every pixel labelled once")).collect();
    assert_eq!(labelled, grid.blocked_mask());
    // Without the map block the grid is the old one: a fortieth of the shorter side, and cells
    // touching an obstacle blocked (more of them).
    let mut plain_sc = sc.clone();
    plain_sc.map = None;
    let (_, ev) = run(&plain_sc, "grid-search", json!({"cell": 0.1}));
    let n_blocked = ev.chunks(STRIDE).filter(|r| r[0] as u8 == EventKind::Cell as u8 && r[6] == 2.0).count();
    assert!(n_blocked > grid.blocked_mask().iter().filter(|b| **b).count());
}

#[test]
fn grid_search_and_rrt_connect_solve_an_imported_map_with_valid_paths() {
    for yaml in ["sample.yaml", "sample-png.yaml"] {
        let sc = import_yaml(yaml);
        for (planner, params) in [
            ("grid-search", json!({})),
            ("grid-search", json!({"search": "bfs", "diagonal": "no"})),
            ("grid-search", json!({"diagonal": "cross-corners"})),
            ("rrt-connect", json!({})),
            ("rrt", json!({"goal_bias": 0.1})),
        ] {
            let (r, _) = run(&sc, planner, params.clone());
            assert!(r.solved, "{yaml} {planner} {params}: {} {:?}", r.status, r.reason);
            for (name, path) in [("raw", &r.path), ("smoothed", &r.smoothed)] {
                if let Some(e) = common::path_problem(&sc, path) {
                    panic!("{yaml} {planner} {params}, {name} path: {e}");
                }
            }
        }
    }
    // A plain PNG (no YAML): 0.05 a pixel from (0, 0).
    let sc = occupancy::import_image(&read("sample.png"), "sample.png", None).unwrap();
    assert_eq!(sc.bounds, [0.0, 0.0, 40.0 * 0.05, 30.0 * 0.05]);
    let (r, _) = run(&sc, "grid-search", json!({}));
    assert!(r.solved && common::path_problem(&sc, &r.path).is_none());
}

fn cli(args: &[&str]) -> (bool, String, String) {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_planarium")).args(args).output().unwrap();
    (out.status.success(), String::from_utf8_lossy(&out.stdout).into(), String::from_utf8_lossy(&out.stderr).into())
}

#[test]
fn the_cli_plans_validates_benches_and_exports_maps() {
    let yaml = format!("{DIR}/sample.yaml");
    let (ok, out, err) = cli(&["plan", &yaml, "--json"]);
    assert!(ok, "{err}");
    let r: Value = serde_json::from_str(&out).unwrap();
    assert_eq!((r["solved"].as_bool(), r["planner"].as_str()), (Some(true), Some("grid-search")));
    // --start and --goal replace the map's.
    let (ok, out, err) =
        cli(&["plan", &yaml, "--planner", "rrt-connect", "--start", "-0.95,-0.45", "--goal", "2.95,2.45", "--json"]);
    assert!(ok, "{err}");
    let r: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(r["path"][0], json!([-0.95, -0.45]));
    // A start in an occupied pixel is named by its flag.
    let (ok, _, err) = cli(&["plan", &yaml, "--start", "0.3,1.0"]);
    assert!(!ok && err.contains("--start: in collision with obstacles["), "{err}");
    for f in ["sample.pgm", "sample.png"] {
        let (ok, out, err) = cli(&["validate", &format!("{DIR}/{f}")]);
        assert!(ok, "{err}");
        assert!(out.contains("\"map\""), "{out}");
    }
    let (ok, out, err) = cli(&["bench", &yaml, "--planners", "grid-search,rrt-connect", "--runs", "2", "--json"]);
    assert!(ok, "{err}");
    assert!(out.contains("grid-search"));
    // export-map then plan on the export; the PNG reads the same as the PGM.
    let dir = std::env::temp_dir().join(format!("planarium-maps-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let prefix = dir.join("exported");
    let prefix = prefix.to_str().unwrap();
    let (ok, _, err) = cli(&["export-map", &yaml, "--cell", "0.1", "--out", prefix, "--png"]);
    assert!(ok, "{err}");
    let exported = std::fs::read_to_string(format!("{prefix}.yaml")).unwrap();
    assert!(exported.starts_with("image: exported.pgm\nresolution: 0.1\norigin: [-1, -0.5, 0.0]\n"), "{exported}");
    let (ok, a, err) = cli(&["validate", &format!("{prefix}.yaml")]);
    assert!(ok, "{err}");
    let from_png =
        occupancy::import_image(&std::fs::read(format!("{prefix}.png")).unwrap(), "x", Some((&exported, "e.yaml")))
            .unwrap();
    let from_pgm = Scenario::from_json(&a).unwrap();
    same_map(&from_pgm, &from_png);
    // Named errors: a YAML whose image is missing, a bad cell.
    std::fs::write(dir.join("lost.yaml"), "image: nowhere.pgm\nresolution: 0.1\n").unwrap();
    let (ok, _, err) = cli(&["plan", dir.join("lost.yaml").to_str().unwrap()]);
    assert!(!ok && err.contains("nowhere.pgm"), "{err}");
    let (ok, _, err) = cli(&["export-map", &yaml, "--cell", "0.00001", "--out", prefix]);
    assert!(!ok && err.contains("--cell: 0.00001 makes a grid of"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn large_maps_open_with_rrt_connect_and_noisy_ones_past_the_obstacle_limit_are_refused() {
    // 1001×1000 pixels, all free but a wall: more pixels than grid-search's max_nodes allows.
    let (w, h) = (1001, 1000);
    let vals: Vec<u16> = (0..w * h).map(|k| if k % w == 500 && k / w > 10 { 0 } else { 254 }).collect();
    let sc = occupancy::import_image(&p5(w, h, 255, &vals), "big.pgm", None).unwrap();
    assert_eq!(sc.planner.as_ref().unwrap().name, "rrt-connect");
    let sc = occupancy::import_image(&p5(1000, 1000, 255, &vals[..1_000_000]), "b.pgm", None).unwrap();
    assert_eq!(sc.planner.as_ref().unwrap().name, "grid-search");
    // A checkerboard of 600×400: 120,000 isolated occupied pixels, a rectangle each.
    let (w, h) = (600, 400);
    let vals: Vec<u16> = (0..w * h).map(|k| if (k % w + k / w) % 2 == 0 { 0 } else { 254 }).collect();
    let e = err_of(occupancy::import_image(&p5(w, h, 255, &vals), "noise.pgm", None));
    assert!(e.starts_with("noise.pgm: the map's occupied pixels make 120000 rectangles; the limit is 100000"), "{e}");
}

#[test]
fn a_map_of_a_million_pixels_is_solved_by_its_own_default_planner() {
    // Was: the map opened with grid-search (a cell a pixel), whose 1,000,000 cells met the default
    // max_nodes (1,000,000) before the first iteration: "node limit · 0 iterations".
    let (w, h) = (1000, 1000);
    let mut values = vec![255u16; w * h];
    // A wall across the middle with a gap at its right end.
    for x in 0..900 {
        values[500 * w + x] = 0;
    }
    let sc = occupancy::import_image(&p5(w, h, 255, &values), "million.pgm", None).unwrap();
    let block = sc.planner.as_ref().expect("the map names its planner");
    assert_eq!(block.name, "grid-search");
    let (r, _) = run(&sc, &block.name, Value::Object(block.params.clone()));
    assert!(r.solved, "{} {:?} after {} iterations", r.status, r.reason, r.stats.iterations);
    assert_eq!(r.stats.nodes, (w * h) as u64);
    assert!(common::path_problem(&sc, &r.path).is_none());
}
