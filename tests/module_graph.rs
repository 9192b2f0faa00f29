//! The crate's top-level modules import one another without a cycle, so `src/lib.rs` can say the
//! data flows one way and mean it.
//!
//! The test reads every file under `src/` (but `src/bin/`, a crate of its own that sees the library
//! as `planarium::`), strips comments, strings and character literals, and collects the paths that
//! name another top-level module: `crate::x` (also inside `use crate::{x, y::z}` groups) and
//! `super::…` chains that climb out of the file's top-level module. Doc links in comments are not
//! edges: they do not make a module depend on another. An edge `a → b` means a file of `a` names
//! something of `b`. The test fails on any cycle of that graph, naming the cycle and, for each of
//! its edges, one place that makes it.
//!
//! It also checks that the drawing in `docs/architecture.md` (the `mermaid` block after "Module
//! graph") lists exactly these edges (but those into the modules used throughout, which import
//! nothing else), so the drawing cannot drift from the code.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

/// Where an edge comes from: the first place (file and line) that makes it.
type Edges = BTreeMap<(String, String), String>;

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("reading {}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// The source with comments, string and char literals blanked (newlines kept, for line numbers).
fn strip(src: &str) -> String {
    let b: Vec<char> = src.chars().collect();
    let mut out = String::with_capacity(src.len());
    let mut i = 0;
    let blank = |c: char| if c == '\n' { '\n' } else { ' ' };
    while i < b.len() {
        let c = b[i];
        let next = b.get(i + 1).copied();
        if c == '/' && next == Some('/') {
            while i < b.len() && b[i] != '\n' {
                out.push(' ');
                i += 1;
            }
        } else if c == '/' && next == Some('*') {
            let mut depth = 0;
            while i < b.len() {
                if b[i] == '/' && b.get(i + 1) == Some(&'*') {
                    depth += 1;
                    out.push_str("  ");
                    i += 2;
                } else if b[i] == '*' && b.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    out.push_str("  ");
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    out.push(blank(b[i]));
                    i += 1;
                }
            }
        } else if c == 'r' && (next == Some('"') || next == Some('#')) && !ident_char(prev(&b, i)) {
            // Raw string r"…" or r#"…"#.
            let mut j = i + 1;
            let mut hashes = 0;
            while b.get(j) == Some(&'#') {
                hashes += 1;
                j += 1;
            }
            if b.get(j) != Some(&'"') {
                out.push(c);
                i += 1;
                continue;
            }
            j += 1;
            while j < b.len() {
                if b[j] == '"' && (0..hashes).all(|k| b.get(j + 1 + k) == Some(&'#')) {
                    j += 1 + hashes;
                    break;
                }
                j += 1;
            }
            for &ch in &b[i..j.min(b.len())] {
                out.push(blank(ch));
            }
            i = j;
        } else if c == '"' {
            out.push(' ');
            i += 1;
            while i < b.len() && b[i] != '"' {
                if b[i] == '\\' {
                    out.push(' ');
                    i += 1;
                }
                if i < b.len() {
                    out.push(blank(b[i]));
                    i += 1;
                }
            }
            out.push(' ');
            i += 1;
        } else if c == '\'' {
            // A char literal ('a', '\n', '\u{..}') or a lifetime ('a): only the former is blanked.
            let close = if next == Some('\\') {
                (i + 2..b.len().min(i + 12)).find(|&j| b[j] == '\'')
            } else if b.get(i + 2) == Some(&'\'') {
                Some(i + 2)
            } else {
                None
            };
            match close {
                Some(j) => {
                    for _ in i..=j {
                        out.push(' ');
                    }
                    i = j + 1;
                }
                None => {
                    out.push(c);
                    i += 1;
                }
            }
        } else {
            out.push(c);
            i += 1;
        }
    }
    out
}

fn prev(b: &[char], i: usize) -> char {
    if i == 0 {
        ' '
    } else {
        b[i - 1]
    }
}

fn ident_char(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

#[derive(Debug, Clone, PartialEq)]
enum Tok {
    Ident(String),
    Punct(char),
    PathSep,
}

fn tokens(src: &str) -> Vec<(Tok, usize)> {
    let b: Vec<char> = src.chars().collect();
    let mut out = Vec::new();
    let mut line = 1;
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        if c == '\n' {
            line += 1;
            i += 1;
        } else if c.is_whitespace() {
            i += 1;
        } else if ident_char(c) {
            let s = i;
            while i < b.len() && ident_char(b[i]) {
                i += 1;
            }
            out.push((Tok::Ident(b[s..i].iter().collect()), line));
        } else if c == ':' && b.get(i + 1) == Some(&':') {
            out.push((Tok::PathSep, line));
            i += 2;
        } else {
            out.push((Tok::Punct(c), line));
            i += 1;
        }
    }
    out
}

/// The module path a file's own items live in: `src/a.rs` and `src/a/mod.rs` are `[a]`,
/// `src/a/b.rs` is `[a, b]`.
fn file_module(rel: &Path) -> Vec<String> {
    let mut parts: Vec<String> = rel.iter().map(|p| p.to_string_lossy().into_owned()).collect();
    let last = parts.pop().unwrap();
    let stem = last.trim_end_matches(".rs");
    if stem != "mod" && stem != "lib" {
        parts.push(stem.to_string());
    }
    parts
}

/// Reads the paths of one group `{ … }` of a `use` tree starting at `toks[i]` (just after `{`)
/// and reports the first segment of each; returns the index after the closing brace.
fn use_group(toks: &[(Tok, usize)], mut i: usize, firsts: &mut Vec<(String, usize)>) -> usize {
    let mut at_start = true;
    let mut depth = 0;
    while i < toks.len() {
        match &toks[i].0 {
            Tok::Punct('{') => depth += 1,
            Tok::Punct('}') => {
                if depth == 0 {
                    return i + 1;
                }
                depth -= 1;
            }
            Tok::Punct(',') if depth == 0 => at_start = true,
            Tok::Ident(name) if depth == 0 && at_start => {
                firsts.push((name.clone(), toks[i].1));
                at_start = false;
            }
            _ => {}
        }
        i += 1;
    }
    i
}

/// At `#[cfg(test)]` (`toks[i]` is `#`): the index after the item it marks, and the name of the
/// module when the item is `mod name;` (a file of test code).
fn cfg_test_item(toks: &[(Tok, usize)], i: usize) -> Option<(usize, Option<String>)> {
    let want = [
        Tok::Punct('#'),
        Tok::Punct('['),
        Tok::Ident("cfg".into()),
        Tok::Punct('('),
        Tok::Ident("test".into()),
        Tok::Punct(')'),
        Tok::Punct(']'),
    ];
    if toks.len() < i + want.len() || toks[i..i + want.len()].iter().zip(&want).any(|(t, w)| &t.0 != w) {
        return None;
    }
    let mut j = i + want.len();
    let mut module = None;
    if toks.get(j).map(|t| &t.0) == Some(&Tok::Ident("mod".into())) {
        if let Some((Tok::Ident(name), _)) = toks.get(j + 1) {
            module = Some(name.clone());
        }
    }
    let mut depth = 0;
    while j < toks.len() {
        match toks[j].0 {
            Tok::Punct(';') if depth == 0 => return Some((j + 1, module)),
            Tok::Punct('{') => depth += 1,
            Tok::Punct('}') => {
                depth -= 1;
                if depth == 0 {
                    return Some((j + 1, None));
                }
            }
            _ => {}
        }
        j += 1;
    }
    Some((j, None))
}

/// The top-level modules a file names, with the line naming each, and the test modules it declares
/// (`#[cfg(test)] mod name;`). Test code (`#[cfg(test)]` items) is not read: a unit test may drive
/// a higher layer without the library depending on it.
fn file_edges(rel: &Path, src: &str) -> (Vec<(String, usize)>, Vec<Vec<String>>) {
    let toks = tokens(&strip(src));
    let base = file_module(rel);
    // Inline `mod name { … }` blocks: the module path at each brace depth.
    let mut inline: Vec<(String, usize)> = Vec::new();
    let mut depth = 0usize;
    let mut found = Vec::new();
    let mut test_modules = Vec::new();
    let mut i = 0;
    while i < toks.len() {
        let (t, line) = (&toks[i].0, toks[i].1);
        if let Some((after, module)) = cfg_test_item(&toks, i) {
            if let Some(name) = module {
                let mut path = base.clone();
                path.extend(inline.iter().map(|(n, _)| n.clone()));
                path.push(name);
                test_modules.push(path);
            }
            i = after;
            continue;
        }
        match t {
            Tok::Punct('{') => {
                depth += 1;
                if i >= 2 && toks[i - 2].0 == Tok::Ident("mod".into()) {
                    if let Tok::Ident(name) = &toks[i - 1].0 {
                        inline.push((name.clone(), depth));
                    }
                }
            }
            Tok::Punct('}') => {
                if inline.last().is_some_and(|&(_, d)| d == depth) {
                    inline.pop();
                }
                depth = depth.saturating_sub(1);
            }
            Tok::Ident(w) if w == "crate" || w == "super" => {
                let preceded_by_sep = i > 0 && toks[i - 1].0 == Tok::PathSep;
                let macro_crate = i > 0 && toks[i - 1].0 == Tok::Punct('$');
                // `pub(crate)`, `pub(super)`, `pub(in crate::x)`: visibility, not a use.
                let tok = |k: usize| i.checked_sub(k).map(|k| &toks[k].0);
                let visibility = (tok(1) == Some(&Tok::Punct('(')) && tok(2) == Some(&Tok::Ident("pub".into())))
                    || (tok(1) == Some(&Tok::Ident("in".into())) && tok(2) == Some(&Tok::Punct('(')));
                if preceded_by_sep || macro_crate || visibility {
                    i += 1;
                    continue;
                }
                // Resolve the leading `crate` / `super::super…` to a module path.
                let mut here: Vec<String> = base.clone();
                here.extend(inline.iter().map(|(n, _)| n.clone()));
                let mut j = i;
                if w == "crate" {
                    here.clear();
                    j += 1;
                } else {
                    // `super::super::…`: up one module per `super`; `j` ends past the last `::`.
                    while toks.get(j).map(|t| &t.0) == Some(&Tok::Ident("super".into())) {
                        here.pop();
                        j += 1;
                        if toks.get(j).map(|t| &t.0) != Some(&Tok::PathSep) {
                            break;
                        }
                        j += 1;
                    }
                }
                if !here.is_empty() {
                    // Still inside a top-level module: that module, unless it is another's.
                    if here[0] != base[0] {
                        found.push((here[0].clone(), line));
                    }
                    i = j;
                    continue;
                }
                // At the crate root: the next segment (or each of a group) is a top-level module.
                if toks.get(j).map(|t| &t.0) == Some(&Tok::PathSep) {
                    j += 1;
                }
                match toks.get(j).map(|t| &t.0) {
                    Some(Tok::Ident(name)) => {
                        found.push((name.clone(), toks[j].1));
                        i = j + 1;
                    }
                    Some(Tok::Punct('{')) => {
                        let mut firsts = Vec::new();
                        i = use_group(&toks, j + 1, &mut firsts);
                        found.extend(firsts);
                    }
                    _ => i = j,
                }
                continue;
            }
            _ => {}
        }
        i += 1;
    }
    (found, test_modules)
}

fn modules_and_edges() -> (BTreeSet<String>, Edges) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&root, &mut files);
    let mut modules = BTreeSet::new();
    let mut edges = Edges::new();
    let mut named = Vec::new();
    let mut test_modules: Vec<Vec<String>> = Vec::new();
    // Parents come before their children in `files` (sorted, `a.rs` before `a/`; `mod.rs` is
    // read first below), so a test module is known before its file is reached.
    files.sort_by_key(|f| (f.components().count(), f.file_name() != Some("mod.rs".as_ref())));
    for f in &files {
        let rel = f.strip_prefix(&root).unwrap();
        if rel.starts_with("bin") || rel == Path::new("lib.rs") {
            continue;
        }
        let module = file_module(rel);
        if test_modules.iter().any(|t| module.starts_with(t)) {
            continue;
        }
        let top = module[0].clone();
        modules.insert(top.clone());
        let src = fs::read_to_string(f).unwrap();
        let (found, tests) = file_edges(rel, &src);
        test_modules.extend(tests);
        for (to, line) in found {
            named.push((top.clone(), to, format!("src/{}:{line}", rel.display())));
        }
    }
    for (from, to, at) in named {
        // Names at the crate root that are not modules (re-exports, `crate::Self`…) are skipped.
        if from != to && modules.contains(&to) {
            edges.entry((from, to)).or_insert(at);
        }
    }
    (modules, edges)
}

/// One cycle through each strongly connected component of more than one module.
fn cycles(modules: &BTreeSet<String>, edges: &Edges) -> Vec<Vec<String>> {
    let out_of = |m: &str| -> Vec<String> { edges.keys().filter(|(a, _)| a == m).map(|(_, b)| b.clone()).collect() };
    let reach = |from: &str| -> BTreeSet<String> {
        let mut seen = BTreeSet::new();
        let mut stack = vec![from.to_string()];
        while let Some(m) = stack.pop() {
            for n in out_of(&m) {
                if seen.insert(n.clone()) {
                    stack.push(n);
                }
            }
        }
        seen
    };
    let reaches: BTreeMap<String, BTreeSet<String>> = modules.iter().map(|m| (m.clone(), reach(m))).collect();
    let mut done = BTreeSet::new();
    let mut found = Vec::new();
    for m in modules {
        if done.contains(m) || !reaches[m].contains(m) {
            continue;
        }
        let scc: BTreeSet<String> =
            modules.iter().filter(|n| reaches[m].contains(*n) && reaches[*n].contains(m)).cloned().collect();
        done.extend(scc.iter().cloned());
        // The shortest cycle through `m` inside its component (breadth first).
        let mut parent: BTreeMap<String, String> = BTreeMap::new();
        let mut queue = std::collections::VecDeque::from([m.clone()]);
        'bfs: while let Some(x) = queue.pop_front() {
            for n in out_of(&x) {
                if !scc.contains(&n) {
                    continue;
                }
                if &n == m {
                    parent.insert(format!("{m}#end"), x.clone());
                    break 'bfs;
                }
                if !parent.contains_key(&n) {
                    parent.insert(n.clone(), x.clone());
                    queue.push_back(n);
                }
            }
        }
        let mut cycle = vec![m.clone()];
        let mut at = parent[&format!("{m}#end")].clone();
        while &at != m {
            cycle.push(at.clone());
            at = parent[&at].clone();
        }
        cycle.push(m.clone());
        cycle.reverse();
        let mut c = cycle;
        c.push(format!("(component: {})", scc.into_iter().collect::<Vec<_>>().join(", ")));
        found.push(c);
    }
    found
}

#[test]
fn top_level_modules_import_without_a_cycle() {
    let (modules, edges) = modules_and_edges();
    assert!(modules.len() > 10, "found too few modules: {modules:?}");
    for (a, b) in [("run", "planners"), ("planners", "space_info"), ("problem", "scenario")] {
        assert!(edges.contains_key(&(a.to_string(), b.to_string())), "the reader missed the edge {a} → {b}: {edges:?}");
    }
    for ((a, b), at) in &edges {
        eprintln!("{a} → {b} ({at})");
    }
    let found = cycles(&modules, &edges);
    if !found.is_empty() {
        let mut msg = String::from("the top-level modules of src/ import in a cycle:\n");
        for c in &found {
            let (component, path) = c.split_last().unwrap();
            msg.push_str(&format!("  {} {component}\n", path.join(" → ")));
            for w in path.windows(2) {
                let at = &edges[&(w[0].clone(), w[1].clone())];
                msg.push_str(&format!("    {} → {}: {at}\n", w[0], w[1]));
            }
        }
        panic!("{msg}");
    }
}

#[test]
fn the_reader_sees_groups_super_and_skips_comments() {
    let src = "//! [`crate::run`]\nuse crate::{motion::X, sampler};\nfn f() { let _ = \"crate::io\"; \
               super::super::problem::g(); crate::space::h(); }\nmod tests { use super::Y; }\n\
               pub(crate) fn g() {}\n";
    let (found, tests) = file_edges(Path::new("robot/a/b.rs"), src);
    let mut got: Vec<String> = found.into_iter().map(|(m, _)| m).collect();
    got.sort();
    // `super::super` from robot::a::b is `robot`, `super::super::problem` is still inside
    // `robot` (robot::problem), so the only top-level modules named are these three.
    assert_eq!(got, ["motion", "sampler", "space"]);
    assert!(tests.is_empty());
    let (top, _) = file_edges(Path::new("planners.rs"), "fn f() { super::run::go(); }");
    assert_eq!(top, [("run".to_string(), 1)]);
    let src = "#[cfg(test)]\nmod tests;\n#[cfg(test)]\nmod more { use crate::run::X; }\n\
               #[cfg(test)]\nfn f() { crate::io::g() }\nuse crate::rng::R;\n";
    let (found, tests) = file_edges(Path::new("math.rs"), src);
    assert_eq!(found, [("rng".to_string(), 7)]);
    assert_eq!(tests, [vec!["math".to_string(), "tests".to_string()]]);
}

/// The `mermaid` block after the "Module graph" heading of docs/architecture.md: its `a --> b`
/// lines.
fn drawn_edges() -> BTreeSet<(String, String)> {
    let doc = fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/architecture.md")).unwrap();
    let start = doc.find("## Module graph").expect("docs/architecture.md has a \"## Module graph\"");
    let rest = &doc[start..];
    let open = rest.find("```mermaid").expect("a mermaid block under \"## Module graph\"");
    let body = &rest[open + "```mermaid".len()..];
    let body = &body[..body.find("```").expect("the mermaid block ends")];
    body.lines()
        .filter_map(|l| {
            let (a, b) = l.split_once("-->")?;
            Some((a.trim().to_string(), b.trim().to_string()))
        })
        .collect()
}

/// Modules used throughout (scalars, the generator, input limits, the run status, the clock): the
/// drawing leaves out the edges into them, so they must import nothing but one another.
const THROUGHOUT: &[&str] = &["math", "rng", "limits", "status", "clock"];

#[test]
fn the_drawing_in_architecture_md_is_the_graph() {
    let (_, edges) = modules_and_edges();
    for ((a, b), at) in &edges {
        assert!(
            !THROUGHOUT.contains(&a.as_str()) || THROUGHOUT.contains(&b.as_str()),
            "{a} is used throughout, so it must not import {b} ({at})"
        );
    }
    let actual: BTreeSet<(String, String)> =
        edges.keys().filter(|(_, b)| !THROUGHOUT.contains(&b.as_str())).cloned().collect();
    let drawn = drawn_edges();
    let missing: Vec<_> = actual.difference(&drawn).map(|(a, b)| format!("{a} --> {b}")).collect();
    let extra: Vec<_> = drawn.difference(&actual).map(|(a, b)| format!("{a} --> {b}")).collect();
    assert!(
        missing.is_empty() && extra.is_empty(),
        "docs/architecture.md's module graph differs from the code:\n  not drawn: {missing:?}\n  \
         drawn but not in the code: {extra:?}"
    );
}

/// `src/lib.rs` declares the modules bottom-up (its doc says each imports only from those below
/// it): every module after all it imports.
#[test]
fn lib_rs_declares_each_module_after_what_it_imports() {
    let (modules, edges) = modules_and_edges();
    let lib = fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("src/lib.rs")).unwrap();
    let order: Vec<String> = strip(&lib)
        .lines()
        .filter_map(|l| {
            let l = l.trim().trim_start_matches("pub ");
            Some(l.strip_prefix("mod ")?.trim_end_matches(';').trim().to_string())
        })
        .collect();
    let missing: Vec<_> = modules.iter().filter(|m| !order.contains(m)).collect();
    assert!(missing.is_empty(), "modules not declared in src/lib.rs: {missing:?}");
    let at = |m: &str| order.iter().position(|o| o == m).unwrap();
    let wrong: Vec<String> = edges
        .iter()
        .filter(|((a, b), _)| at(a) < at(b))
        .map(|((a, b), place)| format!("{a} imports {b}, declared after it ({place})"))
        .collect();
    assert!(wrong.is_empty(), "src/lib.rs declares modules before what they import:\n  {}", wrong.join("\n  "));
}
