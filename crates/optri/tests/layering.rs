//! The layer rule of ARCHITECTURE.md, checked on the source text: a module
//! may name (`crate::x`) only modules of a lower layer, the kernel names no
//! other module of the crate, and the top-level modules form no cycle.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Top-level modules and their layer; a module may use strictly lower layers.
const LAYERS: &[(&str, u32)] = &[
    ("kernel", 0),
    ("error", 1),
    ("timing", 1),
    ("parallel", 1),
    ("interrupt", 2),
    ("spatial", 2),
    ("structures", 3),
    ("graphs", 4),
    ("polygon_program", 5),
    ("criteria", 6),
    ("registry", 7),
    ("io", 8),
    ("request", 9),
    ("internals", 10),
];

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The top-level module a source file belongs to (`None` for `lib.rs`).
fn module_of(src: &Path, file: &Path) -> Option<String> {
    let rel = file.strip_prefix(src).unwrap();
    let first = rel.components().next()?.as_os_str().to_str()?.to_string();
    let name = first.strip_suffix(".rs").unwrap_or(&first).to_string();
    (name != "lib").then_some(name)
}

/// Every `crate::name` in code (comments and doc comments skipped).
fn crate_references(text: &str) -> BTreeSet<String> {
    let mut found = BTreeSet::new();
    for line in text.lines() {
        let code = line.trim_start();
        if code.starts_with("//") {
            continue;
        }
        let code = code.split("//").next().unwrap_or("");
        let mut rest = code;
        while let Some(at) = rest.find("crate::") {
            let after = &rest[at + "crate::".len()..];
            let name: String = after
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect();
            let preceded_by_ident = rest[..at]
                .chars()
                .last()
                .is_some_and(|c| c.is_ascii_alphanumeric() || c == '_');
            if !name.is_empty() && !preceded_by_ident {
                found.insert(name);
            }
            rest = after;
        }
        // `use crate::{a, b}` groups.
        if let Some(group) = code.split("crate::{").nth(1) {
            for item in group.split(['}', ',']) {
                let name: String = item
                    .trim()
                    .chars()
                    .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                    .collect();
                if !name.is_empty() {
                    found.insert(name);
                }
            }
        }
    }
    found
}

fn dependencies() -> BTreeMap<String, BTreeSet<String>> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let layer: BTreeMap<&str, u32> = LAYERS.iter().copied().collect();
    let mut deps: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for file in files {
        let Some(module) = module_of(&src, &file) else {
            continue;
        };
        assert!(
            layer.contains_key(module.as_str()),
            "top-level module '{module}' ({}) has no layer in tests/layering.rs and ARCHITECTURE.md",
            file.display()
        );
        let text = std::fs::read_to_string(&file).unwrap();
        let entry = deps.entry(module.clone()).or_default();
        for name in crate_references(&text) {
            // Crate-root re-exports (`crate::Error`, `crate::PointSet`) are
            // types, not modules; only module names are layered.
            if layer.contains_key(name.as_str()) && name != module {
                entry.insert(name);
            }
        }
    }
    deps
}

#[test]
fn modules_use_only_lower_layers() {
    let layer: BTreeMap<&str, u32> = LAYERS.iter().copied().collect();
    let deps = dependencies();
    assert!(deps.len() >= 10, "found only {} modules", deps.len());
    let mut violations = Vec::new();
    for (module, used) in &deps {
        for u in used {
            if layer[u.as_str()] >= layer[module.as_str()] {
                violations.push(format!(
                    "{module} (layer {}) uses {u} (layer {})",
                    layer[module.as_str()],
                    layer[u.as_str()]
                ));
            }
        }
    }
    assert!(
        violations.is_empty(),
        "upward or sideways imports:\n{}",
        violations.join("\n")
    );
    assert!(
        deps["kernel"].is_empty(),
        "the kernel uses {:?}",
        deps["kernel"]
    );
}

#[test]
fn top_level_modules_form_no_cycle() {
    let deps = dependencies();
    // Kahn's algorithm: repeatedly remove modules that use nothing left.
    let mut left: BTreeMap<String, BTreeSet<String>> = deps.clone();
    while let Some(free) = left
        .iter()
        .find(|(_, used)| used.iter().all(|u| !left.contains_key(u)))
        .map(|(m, _)| m.clone())
    {
        left.remove(&free);
    }
    assert!(left.is_empty(), "import cycle among {:?}", left.keys());
}

#[test]
fn the_checker_sees_imports() {
    let refs = crate_references(
        "use crate::kernel::{orient_sign, Point};\nuse crate::{graphs, structures::PointSet};\n\
         // use crate::io;\nlet x = crate::timing::Phase; /// [`crate::registry`]",
    );
    let names: Vec<&str> = refs.iter().map(String::as_str).collect();
    assert_eq!(names, ["graphs", "kernel", "structures", "timing"]);
}

/// Every library source file with its path relative to `src/` and its text.
fn library_files() -> Vec<(String, String)> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    files.sort();
    files
        .into_iter()
        .map(|f| {
            let rel = f.strip_prefix(&src).unwrap().display().to_string();
            (rel, std::fs::read_to_string(&f).unwrap())
        })
        .collect()
}

/// Does `text` name the external crate `name` in code (`name::`, `use name`)?
fn names_crate(text: &str, name: &str) -> bool {
    text.lines().any(|line| {
        let code = line.trim_start();
        if code.starts_with("//") {
            return false;
        }
        let code = code.split("//").next().unwrap_or("");
        code.match_indices(&format!("{name}::")).any(|(at, _)| {
            !code[..at]
                .chars()
                .last()
                .is_some_and(|c| c.is_ascii_alphanumeric() || c == '_' || c == ':')
        })
    })
}

/// Exact arithmetic has one home: `robust` is named in `kernel/` only, and
/// `spade` (the Delaunay and constrained Delaunay builders) in
/// `structures/` only.
#[test]
fn robust_only_in_the_kernel_and_spade_only_in_structures() {
    let mut violations = Vec::new();
    for (path, text) in library_files() {
        if names_crate(&text, "robust") && !path.starts_with("kernel/") {
            violations.push(format!("{path} names robust"));
        }
        if names_crate(&text, "spade") && !path.starts_with("structures/") {
            violations.push(format!("{path} names spade"));
        }
    }
    assert!(violations.is_empty(), "{}", violations.join("\n"));
}

/// No library file over 1000 lines (a `tests.rs` may be longer): a longer
/// file holds more than one thing and splits along its module docs' seams.
#[test]
fn no_library_file_over_1000_lines() {
    let long: Vec<String> = library_files()
        .into_iter()
        .filter(|(path, _)| !path.ends_with("tests.rs"))
        .filter_map(|(path, text)| {
            let lines = text.lines().count();
            (lines > 1000).then(|| format!("{path}: {lines} lines"))
        })
        .collect();
    assert!(long.is_empty(), "{}", long.join("\n"));
}

#[test]
fn the_crate_checker_sees_paths_not_suffixes() {
    assert!(names_crate("use spade::Triangulation;", "spade"));
    assert!(names_crate("let o = robust::orient2d(a, b, c);", "robust"));
    assert!(!names_crate("// spade::x", "spade"));
    assert!(!names_crate("let x = my_spade::y;", "spade"));
    assert!(!names_crate("use crate::structures::spade::x;", "spade"));
}
