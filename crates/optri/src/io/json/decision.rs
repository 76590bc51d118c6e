//! The decision document (`"document": "decision"`): the answer to an area
//! decision problem (T. S. Vassilev, *Optimal Area Triangulation*, PhD
//! thesis, University of Saskatchewan, 2005, §2.4) with its witness.

use super::{TimingMap, TriangulationReport, SCHEMA_VERSION};
use crate::criteria::area::{AreaDecision, AreaQuestion};
use crate::io::{ReadInput, Threshold};
use crate::timing::Phase;
use serde::ser::{Serialize, Serializer};
use serde_json::Value;

/// An area decision as a JSON document: `criterion`, `bound`
/// (`"at_least"` or `"at_most"`), `threshold` (the triangle area, not
/// doubled, in the input's units, as the nearest double) and
/// `threshold_decimal` (the decimal decided, as given), `answer` (`true`,
/// `false` or `null` for unknown), `method`, `exact`, `witness` (a
/// triangulation document, when the answer is yes) and `timing_ms`.
#[derive(Clone, Copy, Debug)]
pub struct DecisionReport<'a> {
    question: AreaQuestion,
    threshold: &'a Threshold,
    decision: &'a AreaDecision,
    input: Option<&'a ReadInput>,
    timing: Option<&'a [Phase]>,
}

impl<'a> DecisionReport<'a> {
    /// The document of `decision`, the answer to `question` at `threshold`.
    pub fn new(
        question: AreaQuestion,
        threshold: &'a Threshold,
        decision: &'a AreaDecision,
    ) -> Self {
        Self {
            question,
            threshold,
            decision,
            input: None,
            timing: Some(&decision.phases),
        }
    }

    /// The witness described in the user's units of `read` (as
    /// [`TriangulationReport::with_input`]).
    pub fn with_input(self, read: &'a ReadInput) -> Self {
        Self {
            input: Some(read),
            ..self
        }
    }

    /// Reports `phases` as `timing_ms` instead.
    pub fn with_timing(self, phases: &'a [Phase]) -> Self {
        Self {
            timing: Some(phases),
            ..self
        }
    }

    /// The decision described.
    pub fn decision(&self) -> &'a AreaDecision {
        self.decision
    }

    /// The witness's triangulation document, if there is a witness.
    pub fn witness(&self) -> Option<TriangulationReport<'a>> {
        let witness = self.decision.witness.as_ref()?;
        let report = TriangulationReport::new(witness);
        Some(match self.input {
            Some(read) => report.with_input(read),
            None => report,
        })
    }

    /// The document as a JSON value.
    pub fn to_json(&self) -> Value {
        super::to_value(self)
    }
}

/// The fields of a decision document, in the order written.
#[derive(serde::Serialize)]
struct DecisionDocument<'a> {
    schema_version: u32,
    document: &'static str,
    criterion: &'static str,
    bound: &'static str,
    threshold: f64,
    threshold_decimal: &'a str,
    answer: Option<bool>,
    method: &'static str,
    exact: bool,
    witness: Option<TriangulationReport<'a>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    timing_ms: Option<TimingMap<'a>>,
}

impl Serialize for DecisionReport<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        DecisionDocument {
            schema_version: SCHEMA_VERSION,
            document: "decision",
            criterion: self.question.criterion(),
            bound: match self.question {
                AreaQuestion::SmallestAtLeast => "at_least",
                AreaQuestion::LargestAtMost => "at_most",
            },
            threshold: self.threshold.to_f64(),
            threshold_decimal: self.threshold.text(),
            answer: self.decision.answer,
            method: self.decision.method,
            exact: self.decision.exact,
            witness: self.witness(),
            timing_ms: self.timing.map(TimingMap),
        }
        .serialize(serializer)
    }
}
