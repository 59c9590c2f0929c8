//! The invariants of ARCHITECTURE.md that a test can read from the sources.

use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

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

/// Physics crates never depend on the runner or the command line.
#[test]
fn physics_crates_do_not_depend_on_the_runner() {
    for krate in [
        "mechanism",
        "dynamics",
        "gas",
        "gears",
        "friction",
        "balance",
        "metrics",
        "losses",
        "loads",
        "numeric",
    ] {
        let manifest =
            std::fs::read_to_string(root().join(format!("crates/{krate}/Cargo.toml"))).unwrap();
        for forbidden in ["cardan-runner", "cardan =", "\ncardan."] {
            assert!(
                !manifest.contains(forbidden),
                "crates/{krate} depends on {forbidden}"
            );
        }
    }
}

/// The metric registry and the numeric helpers depend on nothing: every crate may read them.
#[test]
fn the_bottom_crates_depend_on_nothing() {
    for krate in ["metrics", "numeric"] {
        let manifest =
            std::fs::read_to_string(root().join(format!("crates/{krate}/Cargo.toml"))).unwrap();
        let dependencies = manifest.split("[dependencies]").nth(1).unwrap_or("");
        assert!(
            dependencies.trim().is_empty(),
            "crates/{krate} has dependencies: {dependencies}"
        );
    }
}

/// The case schema is read before anything runs: its crate never depends on the runner, the
/// reports or the command line.
#[test]
fn the_case_crate_does_not_depend_on_the_runner() {
    let manifest = std::fs::read_to_string(root().join("case/Cargo.toml")).unwrap();
    for forbidden in ["cardan-runner", "cardan-report", "cardan =", "\ncardan."] {
        assert!(!manifest.contains(forbidden), "case depends on {forbidden}");
    }
}

/// The reports are made from an output folder: their crate never depends on the runner (which
/// depends on it) or the command line, nor on the physics: the metrics' units, groups and
/// directions come from the metric registry alone (`cardan-metrics`, issue 37).
#[test]
fn the_report_crate_does_not_depend_on_the_runner() {
    let manifest = std::fs::read_to_string(root().join("report/Cargo.toml")).unwrap();
    for forbidden in [
        "cardan-runner",
        "cardan =",
        "\ncardan.",
        "cardan-dynamics",
        "cardan-gas",
        "cardan-gears",
        "cardan-friction",
        "cardan-balance",
        "cardan-losses",
    ] {
        assert!(
            !manifest.contains(forbidden),
            "report depends on {forbidden}"
        );
    }
}

/// The crates of `cardan-dynamics`'s jobs point one way: the losses (models, budget, engine
/// losses, fmep) and the loads (families, planar solve, energy) sit below the step pipeline
/// (`cardan-pipeline`: the stage contract, the step loop, the summary), and that below the
/// stages (`cardan-dynamics`), which evaluate them; the loads need the mechanism alone.
#[test]
fn the_loss_and_load_crates_sit_below_the_step_loop() {
    let manifest = std::fs::read_to_string(root().join("crates/losses/Cargo.toml")).unwrap();
    for forbidden in [
        "cardan-dynamics",
        "cardan-case",
        "cardan-balance",
        "cardan-runner",
    ] {
        assert!(
            !manifest.contains(forbidden),
            "crates/losses depends on {forbidden}"
        );
    }
    let loads = std::fs::read_to_string(root().join("crates/loads/Cargo.toml")).unwrap();
    let loads = loads.split("[dependencies]").nth(1).unwrap_or("");
    for line in loads.lines().filter(|l| l.starts_with("cardan-")) {
        assert!(
            line.starts_with("cardan-mechanism"),
            "crates/loads depends on {line}: the loads need the mechanism alone"
        );
    }
    // The step pipeline knows the contract, not the stages: it sits below the crate that
    // holds them (dynamics: the gear ratings, the losses' stage, the machine) and the balance.
    let pipeline = std::fs::read_to_string(root().join("crates/pipeline/Cargo.toml")).unwrap();
    let pipeline = pipeline.split("[dependencies]").nth(1).unwrap_or("");
    for line in pipeline.lines().filter(|l| l.starts_with("cardan-")) {
        let name = line.split(['.', ' ', '=']).next().unwrap_or("");
        assert!(
            [
                "cardan-metrics",
                "cardan-losses",
                "cardan-loads",
                "cardan-mechanism"
            ]
            .contains(&name),
            "crates/pipeline depends on {line}: the pipeline needs the loads, the metric \
             registry, the mesh's components (its peaks) and the mechanism alone"
        );
    }
    let dynamics = std::fs::read_to_string(root().join("crates/dynamics/Cargo.toml")).unwrap();
    assert!(["cardan-losses", "cardan-loads", "cardan-pipeline"]
        .iter()
        .all(|c| dynamics.contains(c)));
}

/// The packages a package of `lock` (a Cargo.lock) builds, itself included, by name: the closure
/// of the lock's dependency lists (which also hold dev-dependencies, so the set is if anything
/// too large: a package missing from it is certainly not built).
fn built_by(lock: &Path, package: &str) -> std::collections::BTreeSet<String> {
    let lock: toml::Table = toml::from_str(&std::fs::read_to_string(lock).unwrap()).unwrap();
    let packages = lock["package"].as_array().unwrap();
    let dependencies_of = |name: &str| -> Vec<String> {
        let entry = packages.iter().find(|p| p["name"].as_str() == Some(name));
        let entry = entry.unwrap_or_else(|| panic!("{name} is not in the lock file"));
        let listed = entry.get("dependencies").and_then(|d| d.as_array());
        // An entry is "name" or "name version" when the lock holds two versions.
        listed
            .into_iter()
            .flatten()
            .map(|d| d.as_str().unwrap().split(' ').next().unwrap().to_string())
            .collect()
    };
    let (mut seen, mut todo) = (std::collections::BTreeSet::new(), vec![package.to_string()]);
    while let Some(name) = todo.pop() {
        if seen.insert(name.clone()) {
            todo.extend(dependencies_of(&name));
        }
    }
    seen
}

/// The gear file of `cardan gear` is a crate of its own (`crates/gear-file`, issue 37): it
/// reads, rates and writes a gear pair with `cardan-gears`' physics and never depends on the
/// command line or the runner, directly (its manifest) or through another crate (the lock file).
#[test]
fn the_gear_file_crate_does_not_depend_on_the_command_line_or_the_runner() {
    let manifest = std::fs::read_to_string(root().join("crates/gear-file/Cargo.toml")).unwrap();
    for forbidden in [
        "cardan-runner",
        "cardan-dynamics",
        "cardan =",
        "\ncardan.",
        "../cli",
        "../runner",
    ] {
        assert!(
            !manifest.contains(forbidden),
            "crates/gear-file depends on {forbidden}"
        );
    }
    let built = built_by(&root().join("Cargo.lock"), "cardan-gear-file");
    assert!(built.contains("cardan-gears"), "{built:?}");
    for forbidden in ["cardan", "cardan-runner"] {
        assert!(
            !built.contains(forbidden),
            "cardan-gear-file builds {forbidden}: {built:?}"
        );
    }
}

/// The Python package rates gear files through `cardan-gear-file` and runs cases through the
/// runner; it never builds the command line (`cardan`, with clap, indicatif and the Slurm
/// scripts), directly or through another crate (python/Cargo.lock, its workspace's own).
#[test]
fn the_python_package_does_not_depend_on_the_command_line() {
    let manifest = std::fs::read_to_string(root().join("python/Cargo.toml")).unwrap();
    for forbidden in ["cardan =", "\ncardan.", "../cli"] {
        assert!(
            !manifest.contains(forbidden),
            "python depends on {forbidden}"
        );
    }
    let built = built_by(&root().join("python/Cargo.lock"), "cardan-python");
    assert!(
        built.contains("cardan-gear-file") && built.contains("cardan-runner"),
        "{built:?}"
    );
    assert!(
        !built.contains("cardan"),
        "the Python package builds the command line: {built:?}"
    );
    // The measure itself: the command line builds the runner and the gear file's crate.
    let cli = built_by(&root().join("Cargo.lock"), "cardan");
    assert!(
        cli.contains("cardan-runner") && cli.contains("cardan-gear-file"),
        "{cli:?}"
    );
}

/// The lengths of the functions of a Rust file formatted by rustfmt: (name, first line,
/// lines from `fn` to its closing brace, both counted). A function ends at the first later
/// line that is its indentation and `}`; a declaration without a body is skipped.
fn function_lengths(text: &str) -> Vec<(String, usize, usize)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    for (k, line) in lines.iter().enumerate() {
        let body = line.trim_start();
        let indent = &line[..line.len() - body.len()];
        let mut rest = body;
        for prefix in ["pub(crate) ", "pub(super) ", "pub ", "const ", "unsafe "] {
            rest = rest.strip_prefix(prefix).unwrap_or(rest);
        }
        let Some(name) = rest.strip_prefix("fn ") else {
            continue;
        };
        let name: String = name
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        // The signature runs to the line with the body's `{` (or a `;`: no body).
        let Some(open) = (k..lines.len())
            .find(|&j| lines[j].contains('{') || lines[j].trim_end().ends_with(';'))
        else {
            continue;
        };
        if !lines[open].contains('{') {
            continue;
        }
        let closing = format!("{indent}}}");
        let end = if lines[open].trim_end().ends_with('}') {
            Some(open)
        } else {
            (open + 1..lines.len()).find(|&j| lines[j].trim_end() == closing)
        };
        if let Some(end) = end {
            out.push((name, k + 1, end - k + 1));
        }
    }
    out
}

/// The code stays readable: no source file over 800 lines, no function over 150 (issue 23), in
/// every crate of the workspace.
#[test]
fn files_and_functions_are_short() {
    let mut files = Vec::new();
    for dir in [
        "case/src",
        "runner/src",
        "report/src",
        "cli/src",
        "xtask/src",
        "xtask/gen/src",
        // The Python package's native part: a workspace of its own, held to the same rule.
        "python/src",
    ] {
        rust_files(&root().join(dir), &mut files);
    }
    for entry in std::fs::read_dir(root().join("crates")).unwrap() {
        rust_files(&entry.unwrap().path().join("src"), &mut files);
    }
    assert!(files.len() > 80, "{} files", files.len());
    for file in files {
        let text = std::fs::read_to_string(&file).unwrap();
        let lines = text.lines().count();
        assert!(lines <= 800, "{}: {lines} lines", file.display());
        for (name, line, length) in function_lengths(&text) {
            assert!(
                length <= 150,
                "{}:{line}: fn {name} is {length} lines",
                file.display()
            );
        }
    }
    // The measure itself: a function of three lines, and a declaration without a body.
    let sample = "fn a() {\n    1\n}\ntrait T {\n    fn b();\n}\n";
    assert_eq!(function_lengths(sample), vec![("a".to_string(), 1, 3)]);
}

/// No code outside the mechanisms' own modules names a mechanism: the rest of the code reads
/// bodies, joints and pistons from the topology.
#[test]
fn no_code_outside_a_mechanism_module_names_a_mechanism() {
    let mut files = Vec::new();
    for dir in [
        "crates/dynamics/src",
        "crates/losses/src",
        "crates/loads/src",
        "crates/gas/src",
        "crates/balance/src",
        "case/src",
        "runner/src",
        "report/src",
        "cli/src",
        "crates/gear-file/src",
    ] {
        rust_files(&root().join(dir), &mut files);
    }
    assert!(files.len() > 10);
    // Every registered mechanism, from the registry: its type (`slider_crank` → `SliderCrank`)
    // and its quoted name, and the old enum of mechanisms.
    let mut names = vec!["MechanismKind".to_string()];
    for entry in cardan_mechanism::MECHANISMS {
        let camel: String = entry
            .name
            .split('_')
            .map(|w| {
                let mut c = w.chars();
                c.next()
                    .unwrap()
                    .to_uppercase()
                    .chain(c)
                    .collect::<String>()
            })
            .collect();
        names.push(camel);
        names.push(format!("\"{}\"", entry.name));
    }
    assert!(names.iter().any(|n| n == "Hypotrochoid"), "{names:?}");
    for file in files {
        let text = std::fs::read_to_string(&file).unwrap();
        for name in &names {
            // Doc comments may mention mechanisms; code may not.
            let in_code = text
                .lines()
                .filter(|l| !l.trim_start().starts_with("//"))
                .any(|l| l.contains(name.as_str()));
            assert!(!in_code, "{} names {name}", file.display());
        }
    }
}

/// A crate's module files by module path (`[]`: the crate root, `lib.rs` or `main.rs`;
/// `["losses", "models"]`: `losses/models.rs` or `losses/models/mod.rs`).
fn module_files(src: &Path) -> std::collections::BTreeMap<Vec<String>, PathBuf> {
    let mut files = Vec::new();
    rust_files(src, &mut files);
    let mut modules = std::collections::BTreeMap::new();
    for file in files {
        let relative = file.strip_prefix(src).unwrap();
        let mut path: Vec<String> = relative
            .with_extension("")
            .iter()
            .map(|p| p.to_string_lossy().into_owned())
            .collect();
        if path.last().is_some_and(|l| l == "mod") {
            path.pop();
        }
        if path == ["lib"] || path == ["main"] {
            path.clear();
        }
        modules.insert(path, file);
    }
    modules
}

/// The code of a source file: comments, string literals and `#[cfg(test)]` modules left out.
fn code_of(text: &str) -> String {
    let mut out = String::new();
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '/' if chars.peek() == Some(&'/') => {
                for c in chars.by_ref() {
                    if c == '\n' {
                        out.push('\n');
                        break;
                    }
                }
            }
            '/' if chars.peek() == Some(&'*') => {
                let mut previous = ' ';
                for c in chars.by_ref() {
                    if previous == '*' && c == '/' {
                        break;
                    }
                    previous = c;
                }
            }
            '"' => {
                let mut escaped = false;
                for c in chars.by_ref() {
                    if c == '"' && !escaped {
                        break;
                    }
                    escaped = c == '\\' && !escaped;
                }
                out.push_str("\"\"");
            }
            // A character literal ('"', '{'), not a lifetime ('a).
            '\'' => {
                let rest: String = chars.clone().take(3).collect();
                let mut literal = rest.chars();
                match (literal.next(), literal.next(), literal.next()) {
                    (Some('\\'), _, _) => {
                        chars.by_ref().take_while(|c| *c != '\'').for_each(drop);
                    }
                    (Some(_), Some('\''), _) => {
                        chars.next();
                        chars.next();
                    }
                    _ => out.push(c),
                }
            }
            c => out.push(c),
        }
    }
    // The test modules: what a test imports is not a dependency of the module.
    while let Some(at) = out.find("#[cfg(test)]") {
        let rest = &out[at..];
        let Some(open) = rest.find('{') else { break };
        let is_module = rest[..open].contains("mod ");
        let mut depth = 0;
        let mut end = rest.len();
        for (k, c) in rest[open..].char_indices() {
            match c {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth == 0 {
                        end = open + k + 1;
                        break;
                    }
                }
                _ => {}
            }
        }
        let end = if is_module { end } else { "#[cfg(test)]".len() };
        out.replace_range(at..at + end, "");
    }
    out
}

/// The paths of a `use` tree (`a::{b, c::{d, e as f}}`), each with the name it brings in.
fn use_paths(tree: &str) -> Vec<(Vec<String>, String)> {
    let tree: String = tree.chars().filter(|c| !c.is_whitespace()).collect();
    let mut out = Vec::new();
    fn expand(prefix: &[String], tree: &str, out: &mut Vec<(Vec<String>, String)>) {
        let (head, rest) = match tree.find('{') {
            Some(k) => (&tree[..k], Some(&tree[k + 1..tree.len() - 1])),
            None => (tree, None),
        };
        let mut path = prefix.to_vec();
        let (head, alias) = match head.split_once("as") {
            Some((h, a)) if rest.is_none() && !a.contains(':') => (h, Some(a)),
            _ => (head, None),
        };
        path.extend(head.split("::").filter(|s| !s.is_empty()).map(String::from));
        match rest {
            None => {
                if path.last().is_some_and(|l| l == "self") {
                    path.pop();
                }
                let name = alias.map(String::from).or(path.last().cloned());
                out.push((path, name.unwrap_or_default()));
            }
            Some(inner) => {
                let mut depth = 0;
                let mut start = 0;
                for (k, c) in inner.char_indices() {
                    match c {
                        '{' => depth += 1,
                        '}' => depth -= 1,
                        ',' if depth == 0 => {
                            expand(&path, &inner[start..k], out);
                            start = k + 1;
                        }
                        _ => {}
                    }
                }
                if start < inner.len() {
                    expand(&path, &inner[start..], out);
                }
            }
        }
    }
    expand(&[], &tree, &mut out);
    out
}

/// Whether `c` can be part of an identifier.
fn ident_char(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// The module paths a file's code names: its `use` trees (`pub use` too, except in the crate
/// root, whose re-exports are the crate's face, not a dependency) and the paths in its code that
/// start with `crate::`, `super::`, `self::` or a child module's name; each as written, from
/// the file's module.
fn named_paths(code: &str, root: bool, children: &[String]) -> Vec<Vec<String>> {
    let mut paths = Vec::new();
    let mut rest = code;
    let mut outside_use = String::new();
    while let Some(k) = rest.find("use ") {
        let before = &rest[..k];
        let token_start = before.chars().last().is_none_or(|c| !ident_char(c));
        let Some(end) = rest[k..].find(';') else {
            break;
        };
        if token_start {
            let public = before.trim_end().ends_with("pub") || before.trim_end().ends_with(')');
            outside_use.push_str(before);
            if !(root && public) {
                paths.extend(use_paths(&rest[k + 4..k + end]).into_iter().map(|(p, _)| p));
            }
        } else {
            outside_use.push_str(&rest[..k + end]);
        }
        rest = &rest[k + end + 1..];
    }
    outside_use.push_str(rest);
    let starts: Vec<&str> = ["crate", "super", "self"]
        .into_iter()
        .chain(children.iter().map(String::as_str))
        .collect();
    let chars: Vec<char> = outside_use.chars().collect();
    let text: String = chars.iter().collect();
    for start in starts {
        let pattern = format!("{start}::");
        for (at, _) in text.match_indices(&pattern) {
            let before = text[..at].chars().last();
            if before.is_some_and(|c| ident_char(c) || c == ':') {
                continue;
            }
            let mut path = Vec::new();
            let mut segment = String::new();
            let mut tail = text[at..].chars().peekable();
            while let Some(c) = tail.next() {
                if ident_char(c) {
                    segment.push(c);
                } else if c == ':' && tail.peek() == Some(&':') {
                    tail.next();
                    path.push(std::mem::take(&mut segment));
                } else {
                    break;
                }
            }
            if !segment.is_empty() {
                path.push(segment);
            }
            paths.push(path);
        }
    }
    paths
}

/// The module files of every crate of the workspace, with the edges between them: an edge
/// A → B when A's code names an item of module B (`use crate::b::X`, `super::b::f()`,
/// `crate::X` re-exported by the root from B or a `#[macro_export]` macro of B, a child's
/// `b::f()`), B's file the deepest module
/// file on the path. A file's `mod b;` is not an edge, nor are the crate root's re-exports, nor
/// the code of `#[cfg(test)]` modules.
fn import_graph(src: &Path) -> (Vec<PathBuf>, Vec<Vec<usize>>) {
    let modules = module_files(src);
    let keys: Vec<Vec<String>> = modules.keys().cloned().collect();
    let index = |m: &[String]| keys.iter().position(|k| k == m);
    let codes: Vec<String> = modules
        .values()
        .map(|f| code_of(&std::fs::read_to_string(f).unwrap()))
        .collect();
    // The root's re-exports: name → path.
    let root = index(&[]).unwrap();
    let mut reexports = std::collections::HashMap::new();
    for keyword in ["pub use ", "pub(crate) use "] {
        let mut rest = codes[root].as_str();
        while let Some(k) = rest.find(keyword) {
            let end = k + rest[k..].find(';').unwrap();
            for (path, name) in use_paths(&rest[k + keyword.len()..end]) {
                let path = if path.first().is_some_and(|s| s == "crate") {
                    path[1..].to_vec()
                } else {
                    path
                };
                reexports.insert(name, path);
            }
            rest = &rest[end..];
        }
    }
    // A `#[macro_export]` macro is named at the root (`crate::name!`) but is its file's.
    for (module, code) in keys.iter().zip(&codes) {
        let mut rest = code.as_str();
        while let Some(k) = rest.find("#[macro_export]") {
            rest = &rest[k + 15..];
            if let Some(name) = rest.trim_start().strip_prefix("macro_rules!") {
                let name: String = name
                    .trim_start()
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                let mut path = module.clone();
                path.push(name.clone());
                reexports.insert(name, path);
            }
        }
    }
    let mut edges = vec![Vec::new(); keys.len()];
    for (a, module) in keys.iter().enumerate() {
        let children: Vec<String> = keys
            .iter()
            .filter(|k| k.len() == module.len() + 1 && k.starts_with(module))
            .map(|k| k.last().unwrap().clone())
            .collect();
        for path in named_paths(&codes[a], module.is_empty(), &children) {
            let mut absolute = match path.first().map(String::as_str) {
                Some("crate") => path[1..].to_vec(),
                Some("super") | Some("self") => {
                    let mut m = module.clone();
                    let mut k = 0;
                    while k < path.len() && (path[k] == "super" || path[k] == "self") {
                        if path[k] == "super" {
                            m.pop();
                        }
                        k += 1;
                    }
                    m.extend(path[k..].iter().cloned());
                    m
                }
                Some(first) if children.iter().any(|c| c == first) => {
                    let mut m = module.clone();
                    m.extend(path.iter().cloned());
                    m
                }
                _ => continue,
            };
            // A name the root re-exports is its module's.
            for _ in 0..4 {
                match absolute.first().and_then(|n| reexports.get(n)) {
                    Some(target) if index(&absolute[..1]).is_none() => {
                        let mut p = target.clone();
                        p.extend(absolute[1..].iter().cloned());
                        absolute = p;
                    }
                    _ => break,
                }
            }
            let b = (0..=absolute.len())
                .rev()
                .find_map(|n| index(&absolute[..n]))
                .unwrap();
            if b != a && !edges[a].contains(&b) {
                edges[a].push(b);
            }
        }
    }
    (modules.into_values().collect(), edges)
}

/// The strongly connected components of more than one node (Tarjan).
fn circles(edges: &[Vec<usize>]) -> Vec<Vec<usize>> {
    struct Tarjan<'a> {
        edges: &'a [Vec<usize>],
        index: Vec<Option<usize>>,
        low: Vec<usize>,
        stack: Vec<usize>,
        on_stack: Vec<bool>,
        next: usize,
        out: Vec<Vec<usize>>,
    }
    impl Tarjan<'_> {
        fn visit(&mut self, v: usize) {
            self.index[v] = Some(self.next);
            self.low[v] = self.next;
            self.next += 1;
            self.stack.push(v);
            self.on_stack[v] = true;
            for &w in &self.edges[v] {
                match self.index[w] {
                    None => {
                        self.visit(w);
                        self.low[v] = self.low[v].min(self.low[w]);
                    }
                    Some(i) if self.on_stack[w] => self.low[v] = self.low[v].min(i),
                    Some(_) => {}
                }
            }
            if Some(self.low[v]) == self.index[v] {
                let mut component = Vec::new();
                while let Some(w) = self.stack.pop() {
                    self.on_stack[w] = false;
                    component.push(w);
                    if w == v {
                        break;
                    }
                }
                if component.len() > 1 {
                    component.sort();
                    self.out.push(component);
                }
            }
        }
    }
    let n = edges.len();
    let mut t = Tarjan {
        edges,
        index: vec![None; n],
        low: vec![0; n],
        stack: Vec::new(),
        on_stack: vec![false; n],
        next: 0,
        out: Vec::new(),
    };
    for v in 0..n {
        if t.index[v].is_none() {
            t.visit(v);
        }
    }
    t.out
}

/// Circles left on purpose: the files of the circle (relative to the workspace) and why. Each
/// is a debt to pay, not a design: the test fails when such a circle changes its files.
const ALLOWED_CIRCLES: &[(&[&str], &str)] = &[];

/// No import circle between the module files of a crate: every crate's files are layered (a
/// module's parts may import their siblings, never the module that holds them when it imports
/// them back). A circle is named by its files; one left on purpose is in `ALLOWED_CIRCLES`
/// with its reason.
#[test]
fn no_import_circles_between_the_files_of_a_crate() {
    let mut crates = vec![
        root().join("case"),
        root().join("runner"),
        root().join("report"),
    ];
    crates.extend([
        root().join("cli"),
        root().join("xtask"),
        root().join("xtask/gen"),
    ]);
    for entry in std::fs::read_dir(root().join("crates")).unwrap() {
        crates.push(entry.unwrap().path());
    }
    let (mut found, mut seen) = (Vec::new(), Vec::new());
    for dir in crates {
        let (files, edges) = import_graph(&dir.join("src"));
        for circle in circles(&edges) {
            let names: Vec<String> = circle
                .iter()
                .map(|&f| {
                    let file = files[f].strip_prefix(root()).unwrap_or(&files[f]);
                    file.to_string_lossy().trim_start_matches("./").to_string()
                })
                .collect();
            let allowed = ALLOWED_CIRCLES.iter().position(|(files, _)| {
                files.len() == names.len() && files.iter().all(|f| names.iter().any(|n| n == f))
            });
            if let Some(k) = allowed {
                seen.push(k);
            } else {
                let mut named = Vec::new();
                for (k, &a) in circle.iter().enumerate() {
                    for (l, b) in circle.iter().enumerate() {
                        if edges[a].contains(b) {
                            named.push(format!("{} -> {}", names[k], names[l]));
                        }
                    }
                }
                let edges = named;
                found.push(format!("{}: {}", names.join(", "), edges.join("; ")));
            }
        }
    }
    assert!(found.is_empty(), "import circles:\n{}", found.join("\n"));
    for (k, (files, _)) in ALLOWED_CIRCLES.iter().enumerate() {
        assert!(
            seen.contains(&k),
            "{files:?} is no longer a circle: remove it from ALLOWED_CIRCLES"
        );
    }
}

/// The measure itself: a circle through a parent and its part is found, comments, strings and
/// test modules are not read, a root's re-exports lead to their modules.
#[test]
fn the_import_graph_reads_uses_paths_and_reexports() {
    let code = code_of(
        "use crate::{a::{B, c as d}, e};\n// crate::x\nfn f() { super::g::h(); \"crate::y\"; }\n#[cfg(test)]\nmod tests { use crate::z; }\n",
    );
    let paths = named_paths(&code, false, &[]);
    let want: Vec<Vec<String>> = [
        vec!["crate", "a", "B"],
        vec!["crate", "a", "c"],
        vec!["crate", "e"],
        vec!["super", "g", "h"],
    ]
    .iter()
    .map(|p| p.iter().map(|s| s.to_string()).collect())
    .collect();
    assert_eq!(paths, want);
    assert_eq!(circles(&[vec![1], vec![0], vec![]]), vec![vec![0, 1]]);
    assert!(circles(&[vec![1], vec![2], vec![]]).is_empty());
}
