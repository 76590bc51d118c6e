//! `optri criteria`: the registry listing, as a table or as the JSON
//! document every front end returns ([`optri::io::registry_listing`]).

use crate::args::CriteriaArgs;
use crate::report;
use crate::CliResult;
use serde_json::Value;

pub(crate) fn run(args: CriteriaArgs) -> CliResult<()> {
    let listing = optri::io::registry_listing();
    if args.json {
        return report::emit_json(&listing);
    }
    report::emit(&table(&listing))
}

/// The listing for people: one line per criterion, graph and option.
fn table(listing: &Value) -> String {
    let text = |v: &Value| v.as_str().unwrap_or_default().to_string();
    let names = |v: &Value| {
        let names: Vec<String> = v
            .as_array()
            .map(|a| a.iter().map(text).collect())
            .unwrap_or_default();
        if names.is_empty() {
            "-".to_string()
        } else {
            names.join(",")
        }
    };
    let mut rows = vec![[
        "criterion".to_string(),
        "guarantee".to_string(),
        "inputs".to_string(),
        "options".to_string(),
        "what it optimises".to_string(),
    ]];
    for c in listing["criteria"].as_array().into_iter().flatten() {
        rows.push([
            text(&c["name"]),
            text(&c["optimality"]),
            names(&c["inputs"]),
            names(&c["options"]),
            text(&c["description"]),
        ]);
    }
    let mut out = aligned(&rows);
    out.push('\n');
    let mut rows = vec![[
        "graph".to_string(),
        "options".to_string(),
        "what it is".to_string(),
    ]];
    for g in listing["graphs"].as_array().into_iter().flatten() {
        rows.push([
            text(&g["name"]),
            names(&g["options"]),
            text(&g["description"]),
        ]);
    }
    out.push_str(&aligned(&rows));
    out.push_str(
        "\noptions (the CLI spells them --metric, --alpha, --approximation, --time-limit):\n",
    );
    for o in listing["options"].as_array().into_iter().flatten() {
        out.push_str(&format!(
            "  {}: {} (default {}); values: {}\n",
            text(&o["name"]),
            text(&o["description"]),
            text(&o["default"]),
            text(&o["values"]),
        ));
    }
    out
}

/// Rows as left-aligned columns, two spaces apart.
fn aligned<const N: usize>(rows: &[[String; N]]) -> String {
    let widths: Vec<usize> = (0..N)
        .map(|k| rows.iter().map(|r| r[k].chars().count()).max().unwrap_or(0))
        .collect();
    let mut out = String::new();
    for row in rows {
        let mut line = String::new();
        for (k, cell) in row.iter().enumerate() {
            line.push_str(cell);
            if k + 1 < N {
                line.push_str(&" ".repeat(widths[k] - cell.chars().count() + 2));
            }
        }
        out.push_str(line.trim_end());
        out.push('\n');
    }
    out
}
