//! Reading point sets and writing triangulations and graphs.
//!
//! - [`read`](self::read_points): text, Triangle `.node`, TSPLIB `.tsp`,
//!   GeoJSON, with line-numbered [`Error::Parse`](crate::Error::Parse) errors;
//! - writers: JSON, GeoJSON, Triangle `.node`/`.ele`, SVG (single picture,
//!   graph, multi-panel comparison), and [`write_triangulation`] /
//!   [`write_graph`] choosing the format by extension.
//!
//! All indices in inputs and outputs are 0-based *input* indices.

mod read;
mod svg;
mod write;

pub use read::{read_points, read_points_file, InputFormat};
pub use svg::{graph_to_svg, panels_to_svg, triangulation_to_svg};
pub use write::{
    graph_to_geojson, graph_to_json, triangulation_from_json, triangulation_to_geojson,
    triangulation_to_json, triangulation_to_triangle_files, write_graph, write_triangulation,
    write_triangulation_titled, OutputFormat,
};
