//! The registry listing document (`"document": "criteria"`): every
//! criterion, graph, option, input format and quality measure optri offers,
//! as `optri criteria --json`, Python's `optri.registry()` and the web API's
//! `GET /api/criteria` all return it (one function, so the three cannot
//! differ). `docs/json-schema.md` lists its fields.

use super::json::SCHEMA_VERSION;
use super::InputFormat;
use crate::criteria::OPTIONS;
use crate::registry::{Criterion, GraphKind};
use crate::structures::Measure;
use serde_json::{json, Value};

/// The registry listing: what this build of optri computes and how to ask
/// for it.
pub fn registry_listing() -> Value {
    let criteria: Vec<Value> = Criterion::ALL
        .iter()
        .map(|&c| {
            let info = c.info();
            json!({
                "name": info.name,
                "description": info.description,
                "optimality": info.optimality.name(),
                "guarantee": info.optimality.statement(),
                "inputs": c.inputs().iter().map(|k| k.name()).collect::<Vec<_>>(),
                "options": info.options,
                "reference": info.reference,
                "needs_elevations": info.needs_elevations,
                "measure": info.measure.map(|m| m.name()),
            })
        })
        .collect();
    let graphs: Vec<Value> = GraphKind::ALL
        .iter()
        .map(|&k| {
            json!({
                "name": k.name(),
                "description": k.description(),
                "options": k.options(),
            })
        })
        .collect();
    let options: Vec<Value> = OPTIONS
        .iter()
        .map(|o| {
            json!({
                "name": o.name,
                "description": o.description,
                "values": o.values,
                "default": o.default,
                "every_run": o.every_run,
            })
        })
        .collect();
    let measures: Vec<Value> = Measure::ALL
        .iter()
        .map(|m| json!({"name": m.name(), "label": m.label(), "better": m.better().name()}))
        .collect();
    json!({
        "document": "criteria",
        "schema_version": SCHEMA_VERSION,
        "optri_version": env!("CARGO_PKG_VERSION"),
        "criteria": criteria,
        "graphs": graphs,
        "options": options,
        "input_formats": InputFormat::ALL.iter().map(|f| f.name()).collect::<Vec<_>>(),
        "measures": measures,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_listing_names_every_registered_criterion_graph_and_option() {
        let v = registry_listing();
        assert_eq!(v["document"], "criteria");
        let names = |key: &str| -> Vec<String> {
            v[key]
                .as_array()
                .unwrap()
                .iter()
                .map(|e| e["name"].as_str().unwrap().to_string())
                .collect()
        };
        let criteria: Vec<&str> = Criterion::ALL.iter().map(|c| c.name()).collect();
        assert_eq!(names("criteria"), criteria);
        let graphs: Vec<&str> = GraphKind::ALL.iter().map(|k| k.name()).collect();
        assert_eq!(names("graphs"), graphs);
        assert_eq!(
            names("options"),
            ["metric", "alpha", "approximation", "time_limit"]
        );
        assert_eq!(v["criteria"][1]["options"], json!(["metric"]));
        assert_eq!(v["criteria"][0]["inputs"], json!(["points", "polygon"]));
        assert_eq!(names("measures").len(), Measure::ALL.len());
    }
}
