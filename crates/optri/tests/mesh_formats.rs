//! The mesh formats: OBJ, PLY (ASCII and binary) and OFF outputs checked
//! literally and against small independent parsers written here, read back
//! through `optri::io::read` where optri reads the format (PLY, OBJ); PLY
//! files in other tools' conventions; and every kind of bad input, which
//! must be an error naming its line or byte, never a panic or a huge
//! allocation.

use optri::io::{
    self, Arithmetic, GraphReport, InputFormat, OutputFormat, PlyEncoding, ReadInput, ReadOptions,
    Source, TriangulationReport, WriteOptions,
};
use optri::{delaunay, Error, PointSet};
use optri_oracle::inputs::{lattice_points, uniform_in_square};
use rand::rngs::StdRng;
use rand::SeedableRng;
use std::path::{Path, PathBuf};

type Point = [f64; 2];

const SEED_MESHES: u64 = 4417;

/// A fresh directory for one test's files.
fn scratch(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("optri-mesh-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn read_bytes(bytes: &[u8], format: Option<InputFormat>) -> optri::Result<ReadInput> {
    io::read(
        Source::Bytes(bytes),
        &ReadOptions::default().with_format(format),
    )
}

/// The error of a read that must fail, as `(line, message)`.
fn parse_error(read: optri::Result<ReadInput>) -> (usize, String) {
    match read {
        Err(Error::Parse { line, message }) => (line, message),
        other => panic!("expected a parse error, got {other:?}"),
    }
}

/// Point sets with duplicates, negative values and extreme magnitudes, and
/// elevations that agree on duplicates.
fn meshes() -> Vec<(Vec<Point>, Vec<f64>)> {
    let mut rng = StdRng::seed_from_u64(SEED_MESHES);
    let mut sets = Vec::new();
    for scale in [1.0, 1e-30, 3e40] {
        let mut pts: Vec<Point> = uniform_in_square(&mut rng, 25, 1.0)
            .into_iter()
            .map(|p| [p[0] * scale - 0.25 * scale, p[1] * scale])
            .collect();
        pts.push(pts[4]);
        sets.push(pts);
    }
    let mut lattice = lattice_points(&mut rng, 30, -4..4, -4..4);
    lattice.extend([lattice[0], [9.0, 9.0], [-9.0, 9.0]]);
    sets.push(lattice);
    sets.into_iter()
        .map(|pts| {
            let z = pts
                .iter()
                .map(|p| (p[0] * 3.0 - p[1]).abs() * 1e-7 - 2.5e-3)
                .collect();
            (pts, z)
        })
        .collect()
}

/// `(vertices, faces)` of an OBJ written by optri: `v x y z` and `f a b c`
/// (1-based) or `l a b`.
fn parse_obj(text: &str) -> (Vec<[f64; 3]>, Vec<Vec<u32>>) {
    let (mut vertices, mut cells) = (Vec::new(), Vec::new());
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let mut tokens = line.split(' ');
        match tokens.next() {
            Some("v") => vertices.extend(vertex_lines(&mut [&line[2..]].into_iter(), 1)),
            Some("f" | "l") => cells.push(tokens.map(|t| t.parse::<u32>().unwrap() - 1).collect()),
            other => panic!("unexpected OBJ statement {other:?}"),
        }
    }
    (vertices, cells)
}

/// The numbers of a line separated by single spaces.
fn numbers<T: std::str::FromStr>(line: &str) -> Vec<T>
where
    T::Err: std::fmt::Debug,
{
    line.split(' ').map(|t| t.parse().unwrap()).collect()
}

/// The `n` vertex lines `x y z` that follow in `lines`.
fn vertex_lines<'a>(lines: &mut impl Iterator<Item = &'a str>, n: usize) -> Vec<[f64; 3]> {
    (0..n)
        .map(|_| {
            let v: Vec<f64> = numbers(lines.next().unwrap());
            [v[0], v[1], v[2]]
        })
        .collect()
}

/// The face lines `3 a b c` of `lines`, as `[a, b, c]`.
fn face_lines<'a>(lines: impl Iterator<Item = &'a str>) -> Vec<Vec<u32>> {
    lines
        .map(|l| {
            let f: Vec<u32> = numbers(l);
            assert_eq!(f[0], 3);
            f[1..].to_vec()
        })
        .collect()
}

/// `(vertices, faces)` of an OFF written by optri.
fn parse_off(text: &str) -> (Vec<[f64; 3]>, Vec<Vec<u32>>) {
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("OFF"));
    let counts: Vec<usize> = numbers(lines.next().unwrap());
    let vertices = vertex_lines(&mut lines, counts[0]);
    let faces = face_lines(lines);
    assert_eq!([counts[1], counts[2]], [faces.len(), 0]);
    (vertices, faces)
}

/// `(vertices, faces)` of a PLY written by optri, ASCII or binary
/// little-endian: the header's layout is the one optri writes.
fn parse_ply(bytes: &[u8]) -> (Vec<[f64; 3]>, Vec<Vec<u32>>) {
    let end = b"end_header\n";
    let at = bytes.windows(end.len()).position(|w| w == end).unwrap() + end.len();
    let header = std::str::from_utf8(&bytes[..at]).unwrap();
    let count = |element: &str| -> usize {
        let line = header
            .lines()
            .find(|l| l.starts_with(&format!("element {element} ")))
            .unwrap_or("element - 0");
        line.rsplit(' ').next().unwrap().parse().unwrap()
    };
    let (n, faces, edges) = (count("vertex"), count("face"), count("edge"));
    let body = &bytes[at..];
    if header.contains("format ascii 1.0") {
        let mut lines = std::str::from_utf8(body).unwrap().lines();
        let vertices = vertex_lines(&mut lines, n);
        let cells: Vec<Vec<u32>> = if faces > 0 {
            face_lines(lines)
        } else {
            lines.map(numbers).collect()
        };
        assert_eq!(cells.len(), faces + edges);
        return (vertices, cells);
    }
    assert!(header.contains("format binary_little_endian 1.0"));
    let f64_at = |k: usize| f64::from_le_bytes(body[k..k + 8].try_into().unwrap());
    let i32_at = |k: usize| i32::from_le_bytes(body[k..k + 4].try_into().unwrap()) as u32;
    let vertices = (0..n)
        .map(|i| [f64_at(24 * i), f64_at(24 * i + 8), f64_at(24 * i + 16)])
        .collect();
    let rest = &body[24 * n..];
    let cells: Vec<Vec<u32>> = if faces > 0 {
        assert_eq!(rest.len(), 13 * faces);
        (0..faces)
            .map(|k| {
                assert_eq!(rest[13 * k], 3);
                let base = 24 * n + 13 * k + 1;
                (0..3).map(|j| i32_at(base + 4 * j)).collect()
            })
            .collect()
    } else {
        assert_eq!(rest.len(), 8 * edges);
        (0..edges)
            .map(|k| vec![i32_at(24 * n + 8 * k), i32_at(24 * n + 8 * k + 4)])
            .collect()
    };
    (vertices, cells)
}

/// The mesh in `path` by the parser of its format.
fn parse_mesh(path: &Path) -> (Vec<[f64; 3]>, Vec<Vec<u32>>) {
    let bytes = std::fs::read(path).unwrap();
    match path.extension().unwrap().to_str().unwrap() {
        "obj" => parse_obj(std::str::from_utf8(&bytes).unwrap()),
        "off" => parse_off(std::str::from_utf8(&bytes).unwrap()),
        "ply" => parse_ply(&bytes),
        other => panic!("not a mesh: {other}"),
    }
}

/// Every mesh output of each set, with and without elevations: the
/// vertices are the input points in input order (duplicates too) at their
/// elevation or 0, the faces are the triangulation's triangles, and reading
/// a PLY or OBJ back gives the points and elevations as `f64`-identical.
#[test]
fn every_mesh_output_holds_the_input_points_and_the_triangles() {
    let dir = scratch("round-trip");
    let mut files = 0;
    for (k, (pts, z)) in meshes().into_iter().enumerate() {
        for with_z in [false, true] {
            let mut set = PointSet::new(&pts).unwrap();
            if with_z {
                set = set.with_elevations(&z).unwrap();
            }
            let t = delaunay(&set).unwrap();
            let report = TriangulationReport::new(&t);
            let expected_z: Vec<f64> = if with_z {
                z.clone()
            } else {
                vec![0.0; pts.len()]
            };
            for (name, encoding) in [
                ("t.obj", PlyEncoding::default()),
                ("t.off", PlyEncoding::default()),
                ("t.ply", PlyEncoding::BinaryLittleEndian),
                ("a.ply", PlyEncoding::Ascii),
            ] {
                let path = dir.join(format!("{k}-{with_z}-{name}"));
                let options = WriteOptions::default().with_ply_encoding(encoding);
                assert_eq!(
                    io::write(report, &path, &options).unwrap(),
                    std::slice::from_ref(&path)
                );
                let (vertices, faces) = parse_mesh(&path);
                let xy: Vec<Point> = vertices.iter().map(|v| [v[0], v[1]]).collect();
                let zs: Vec<f64> = vertices.iter().map(|v| v[2]).collect();
                assert_eq!(xy, pts, "{name}");
                assert_eq!(zs, expected_z, "{name}");
                let faces: Vec<[u32; 3]> = faces.iter().map(|f| [f[0], f[1], f[2]]).collect();
                assert_eq!(faces, t.triangles(), "{name}");
                files += 1;
                if name.ends_with(".off") {
                    continue;
                }
                let read = io::read(Source::Path(&path), &ReadOptions::default()).unwrap();
                assert_eq!(read.input.points(), pts, "{name}");
                assert_eq!(read.elevations.as_deref(), Some(&expected_z[..]), "{name}");
                // The faces are skipped, and said to be.
                assert!(
                    read.warnings.iter().any(|w| w.contains("ignored")),
                    "{name}: {:?}",
                    read.warnings
                );
            }
        }
    }
    assert_eq!(files, 4 * 2 * 4);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A small triangulation with a merged duplicate (input index 4, in no
/// face) and elevations, written in every mesh format, checked literally.
#[test]
fn golden_mesh_outputs() {
    let dir = scratch("golden");
    let pts = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.5], [0.0, 1.5], [0.0, 0.0]];
    let z = [1.0, -0.5, 2.5e-30, 0.0, 1.0];
    let set = PointSet::new(&pts).unwrap().with_elevations(&z).unwrap();
    let t = delaunay(&set).unwrap();
    assert_eq!(t.triangles(), [[0, 1, 2], [0, 2, 3]]);
    let report = TriangulationReport::new(&t);
    let written = |name: &str, encoding: PlyEncoding| -> Vec<u8> {
        let path = dir.join(name);
        let options = WriteOptions::default().with_ply_encoding(encoding);
        io::write(report, &path, &options).unwrap();
        std::fs::read(&path).unwrap()
    };
    let text = |name: &str, encoding| String::from_utf8(written(name, encoding)).unwrap();
    assert_eq!(
        text("g.obj", PlyEncoding::default()),
        "# optri: every input point is a vertex (merged duplicates too), then the \
         counter-clockwise triangles (f), 1-based\n\
         v 0 0 1\nv 2 0 -0.5\nv 2 1.5 2.5e-30\nv 0 1.5 0\nv 0 0 1\n\
         f 1 2 3\nf 1 3 4\n"
    );
    assert_eq!(
        text("g.off", PlyEncoding::default()),
        "OFF\n5 2 0\n0 0 1\n2 0 -0.5\n2 1.5 2.5e-30\n0 1.5 0\n0 0 1\n3 0 1 2\n3 0 2 3\n"
    );
    let header = |format: &str| {
        format!(
            "ply\nformat {format} 1.0\n\
             comment optri: every input point is a vertex (merged duplicates too), indices \
             0-based\n\
             element vertex 5\nproperty double x\nproperty double y\nproperty double z\n\
             element face 2\nproperty list uchar int vertex_indices\nend_header\n"
        )
    };
    assert_eq!(
        text("g.ply", PlyEncoding::Ascii),
        header("ascii") + "0 0 1\n2 0 -0.5\n2 1.5 2.5e-30\n0 1.5 0\n0 0 1\n3 0 1 2\n3 0 2 3\n"
    );
    let mut binary = header("binary_little_endian").into_bytes();
    for (p, z) in pts.iter().zip(z) {
        for v in [p[0], p[1], z] {
            binary.extend(v.to_le_bytes());
        }
    }
    for face in [[0i32, 1, 2], [0, 2, 3]] {
        binary.push(3);
        for v in face {
            binary.extend(v.to_le_bytes());
        }
    }
    assert_eq!(written("g.ply", PlyEncoding::BinaryLittleEndian), binary);
    // Binary is the default.
    assert_eq!(WriteOptions::default().ply, PlyEncoding::BinaryLittleEndian);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A graph is written as OBJ lines and a PLY `edge` element; OFF, which
/// has no edges, refuses it naming the format, as it refuses a comparison.
#[test]
fn graphs_are_obj_lines_and_ply_edges_and_off_refuses_them() {
    let dir = scratch("graph");
    let pts = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [3.0, 3.0]];
    let edges = [[0, 1], [0, 2], [1, 3]];
    let graph = GraphReport::new(&pts, &edges);
    let options = WriteOptions::default().with_ply_encoding(PlyEncoding::Ascii);
    io::write(graph, &dir.join("g.obj"), &options).unwrap();
    assert_eq!(
        std::fs::read_to_string(dir.join("g.obj")).unwrap(),
        "# optri: every input point is a vertex (merged duplicates too), then the edges (l), \
         1-based\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 3 3 0\nl 1 2\nl 1 3\nl 2 4\n"
    );
    io::write(graph, &dir.join("g.ply"), &options).unwrap();
    let ply = std::fs::read_to_string(dir.join("g.ply")).unwrap();
    assert!(
        ply.ends_with(
            "element edge 3\nproperty int vertex1\nproperty int vertex2\nend_header\n\
             0 0 0\n1 0 0\n0 1 0\n3 3 0\n0 1\n0 2\n1 3\n"
        ),
        "{ply}"
    );
    let binary = dir.join("b.ply");
    io::write(graph, &binary, &WriteOptions::default()).unwrap();
    let (vertices, cells) = parse_mesh(&binary);
    assert_eq!(vertices.len(), 4);
    assert_eq!(cells, [vec![0, 1], vec![0, 2], vec![1, 3]]);
    // Read back, the edges are skipped with a warning.
    let read = io::read(Source::Path(&binary), &ReadOptions::default()).unwrap();
    assert_eq!(read.input.points(), pts);
    assert!(read.warnings.iter().any(|w| w.contains("'edge'")));
    let off = dir.join("g.off");
    let e = io::write(graph, &off, &options).unwrap_err().to_string();
    assert!(e.contains("g.off") && e.contains("OFF holds faces"), "{e}");
    assert!(!off.exists());
    let e = OutputFormat::from_path_for_graph(&off)
        .unwrap_err()
        .to_string();
    assert!(e.contains(".obj or .ply"), "{e}");
    let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    let results = optri::compare(
        &PointSet::new(&square).unwrap(),
        &[optri::Criterion::Delaunay],
        &optri::Options::default(),
    );
    for name in ["c.obj", "c.ply", "c.off"] {
        let e = io::write(
            io::ComparisonReport::new(&results),
            &dir.join(name),
            &options,
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("a comparison"), "{e}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `element vertex` with float `x y z`, colours and normals, then faces
/// under `vertex_index` with a `uchar`/`int` list, in each encoding of the
/// PLY specification; all three read as the same points and elevations.
#[test]
fn ply_files_of_other_tools_are_read() {
    let header = |format: &str| {
        format!(
            "ply\r\nformat {format} 1.0\r\ncomment made by another tool\r\nobj_info scanned\r\n\
             element vertex 3\r\nproperty float x\r\nproperty float y\r\nproperty float z\r\n\
             property uchar red\r\nproperty uchar green\r\nproperty uchar blue\r\n\
             property float32 nx\r\n\
             element face 1\r\nproperty list uint8 int32 vertex_index\r\n\
             element material 0\r\nproperty uchar ambient_red\r\nend_header\r\n"
        )
    };
    let vertices = [[0.5f32, -1.0, 2.0], [3.25, 0.0, -0.125], [0.0, 4.0, 8.0]];
    let ascii = header("ascii")
        + "0.5 -1 2 255 0 0 0.1\r\n3.25 0 -0.125 0 255 0 0\r\n\r\n0 4 8 0 0 255 1e-3\r\n3 0 1 2\r\n";
    let binary = |big: bool| {
        let mut bytes = header(if big {
            "binary_big_endian"
        } else {
            "binary_little_endian"
        })
        .into_bytes();
        let f32_bytes = |v: f32| {
            if big {
                v.to_be_bytes()
            } else {
                v.to_le_bytes()
            }
        };
        for v in vertices {
            for c in v {
                bytes.extend(f32_bytes(c));
            }
            bytes.extend([9, 9, 9]);
            bytes.extend(f32_bytes(f32::NAN)); // a skipped property may be anything
        }
        bytes.push(3);
        for i in [0i32, 1, 2] {
            bytes.extend(if big {
                i.to_be_bytes()
            } else {
                i.to_le_bytes()
            });
        }
        bytes
    };
    let points: Vec<Point> = vertices
        .iter()
        .map(|v| [v[0].into(), v[1].into()])
        .collect();
    let z: Vec<f64> = vertices.iter().map(|v| v[2].into()).collect();
    for (name, bytes) in [
        ("ascii", ascii.into_bytes()),
        ("little", binary(false)),
        ("big", binary(true)),
    ] {
        for format in [None, Some(InputFormat::Ply)] {
            let read = read_bytes(&bytes, format).unwrap();
            assert_eq!(read.format, Some(InputFormat::Ply), "{name}");
            assert_eq!(read.input.points(), points, "{name}");
            assert_eq!(read.elevations.as_deref(), Some(&z[..]), "{name}");
            let warnings = read.warnings.join("; ");
            assert!(
                warnings.contains("'red', 'green', 'blue', 'nx'")
                    && warnings.contains("'face' (1 items)")
                    && warnings.contains("'material' (0 items)"),
                "{name}: {warnings}"
            );
        }
    }
    // Without z there are no elevations; integer coordinates of any type.
    let mut shorts = b"ply\nformat binary_big_endian 1.0\nelement vertex 3\n\
        property short y\nproperty int8 x\nend_header\n"
        .to_vec();
    for (y, x) in [(-300i16, -2i8), (0, 5), (7, 0)] {
        shorts.extend(y.to_be_bytes());
        shorts.push(x as u8);
    }
    let read = read_bytes(&shorts, None).unwrap();
    assert_eq!(
        read.input.points(),
        [[-2.0, -300.0], [5.0, 0.0], [0.0, 7.0]]
    );
    assert_eq!(read.elevations, None);
    assert!(read.warnings.is_empty(), "{:?}", read.warnings);
}

/// PLY is recognised by its magic line in any source; OBJ only by its
/// extension or name (a `v x y` file is otherwise not a point file).
#[test]
fn ply_is_sniffed_and_obj_is_named() {
    let ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n\
               end_header\n0 0\n1 0\n0 1\n";
    assert_eq!(InputFormat::sniff(ply), InputFormat::Ply);
    assert_eq!(InputFormat::sniff("plyx\n1 2\n"), InputFormat::Text);
    let read = io::read(Source::Text(ply), &ReadOptions::default()).unwrap();
    assert_eq!(read.format, Some(InputFormat::Ply));
    let with_bom = [b"\xef\xbb\xbf".as_slice(), ply.as_bytes()].concat();
    assert_eq!(read_bytes(&with_bom, None).unwrap().input, read.input);
    let obj = "# cube corner\nmtllib a.mtl\no thing\nv 0 0 1\nv 1 0 2 1\nvt 0.5 0.5\n\
               vn 0 0 1\nv 0 1 3 0.2 0.3 0.4\ng side\nusemtl red\nf 1/1/1 2/1/1 3/1/1\n\
               l 1 2\ns off\n";
    assert_eq!(InputFormat::sniff(obj), InputFormat::Text);
    assert!(read_bytes(obj.as_bytes(), None).is_err());
    let dir = scratch("sniff");
    for (name, format) in [("m.OBJ", None), ("m.txt", Some(InputFormat::Obj))] {
        let path = dir.join(name);
        std::fs::write(&path, obj).unwrap();
        let options = ReadOptions::default().with_format(format);
        let read = io::read(Source::Path(&path), &options).unwrap();
        assert_eq!(read.format, Some(InputFormat::Obj));
        assert_eq!(read.input.points(), [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
        assert_eq!(read.elevations, Some(vec![1.0, 2.0, 3.0]));
        assert_eq!(
            read.warnings,
            ["1 faces (f) and 1 lines (l) ignored: the vertices are read as points"]
        );
    }
    let read = read_bytes(b"v 1 2\nv 3 4\nv 0 7\n", Some(InputFormat::Obj)).unwrap();
    assert_eq!(read.elevations, None);
    assert!(read.warnings.is_empty());
    assert_eq!(InputFormat::from_name("PLY").unwrap(), InputFormat::Ply);
    assert_eq!(InputFormat::from_name("obj").unwrap(), InputFormat::Obj);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// ASCII PLY and OBJ keep their decimals like every text reader; binary
/// doubles are read at their shortest decimals, like a front end's doubles,
/// so a binary PLY written by optri triangulates as its decimal input did;
/// a `float` is not the decimal it was rounded from.
#[test]
fn decimals_of_text_and_shortest_decimals_of_binary_values() {
    let ascii = "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\n\
                 property double y\nend_header\n0.1 0.1\n0.2 0.2\n0.3 0.5\n";
    let read = read_bytes(ascii.as_bytes(), None).unwrap();
    assert_eq!(read.arithmetic, Arithmetic::DecimalExact);
    assert_eq!(read.scale_exponent(), 1);
    let read = read_bytes(b"v 0.1 0.1\nv 0.2 0.2\nv 0.3 0.5\n", Some(InputFormat::Obj)).unwrap();
    assert_eq!(read.scale_exponent(), 1);
    let binary = |ty: &str, values: &[f64]| {
        let mut bytes = format!(
            "ply\nformat binary_little_endian 1.0\nelement vertex {}\nproperty {ty} x\n\
             property {ty} y\nend_header\n",
            values.len() / 2
        )
        .into_bytes();
        for &v in values {
            if ty == "double" {
                bytes.extend(v.to_le_bytes());
            } else {
                bytes.extend((v as f32).to_le_bytes());
            }
        }
        read_bytes(&bytes, None).unwrap()
    };
    let values = [0.1, 0.1, 0.2, 0.2, 0.3, 0.5];
    let doubles = binary("double", &values);
    assert_eq!(doubles.arithmetic, Arithmetic::DecimalExact);
    assert_eq!(
        doubles.scaled.unwrap().points,
        [[1.0, 1.0], [2.0, 2.0], [3.0, 5.0]]
    );
    assert_eq!(binary("float", &values).arithmetic, Arithmetic::Binary64);
}

/// Bad PLY headers: each error names its line.
#[test]
fn bad_ply_headers_name_their_line() {
    let vertex = "element vertex 1\nproperty double x\nproperty double y\n";
    for (text, line, needle) in [
        (
            format!("ply\nformat binary_middle_endian 1.0\n{vertex}end_header\n"),
            2,
            "unsupported PLY format 'binary_middle_endian'",
        ),
        (
            format!("ply\nformat ascii 2.0\n{vertex}end_header\n"),
            2,
            "unsupported PLY version '2.0'",
        ),
        (
            format!("ply\nformat ascii 1.0\nformat ascii 1.0\n{vertex}end_header\n"),
            3,
            "a second 'format'",
        ),
        (
            format!("ply\n{vertex}end_header\n1 2\n"),
            0,
            "no 'format' line",
        ),
        (
            format!("ply\nformat ascii 1.0\n{vertex}"),
            0,
            "no 'end_header'",
        ),
        (
            "ply\nformat ascii 1.0\nproperty double x\nend_header\n".to_string(),
            3,
            "a property before any element",
        ),
        (
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty real x\nend_header\n".to_string(),
            4,
            "unknown property type 'real'",
        ),
        (
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty list float int x\nend_header\n"
                .to_string(),
            4,
            "length type of a list",
        ),
        (
            "ply\nformat ascii 1.0\nelement vertex -1\nend_header\n".to_string(),
            3,
            "not a non-negative integer: '-1'",
        ),
        (
            format!("ply\nformat ascii 1.0\n{vertex}property float x\nend_header\n"),
            6,
            "two properties 'x'",
        ),
        (
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty double x\nend_header\n0\n"
                .to_string(),
            3,
            "no property 'y'",
        ),
        (
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty double y\nproperty list uchar \
             int x\nend_header\n0 1 0\n"
                .to_string(),
            3,
            "'x' is a list",
        ),
        (
            "ply\nformat ascii 1.0\nelement face 0\nend_header\n".to_string(),
            0,
            "no 'vertex' element",
        ),
        (
            format!("ply\nformat ascii 1.0\n{vertex}{vertex}end_header\n"),
            6,
            "a second 'vertex'",
        ),
        (
            format!("ply\nformat ascii 1.0\n{vertex}bogus line\nend_header\n"),
            6,
            "not a PLY header line: 'bogus line'",
        ),
        (format!("not ply\n{vertex}"), 1, "not a PLY file"),
    ] {
        let (got, m) = parse_error(read_bytes(text.as_bytes(), Some(InputFormat::Ply)));
        assert_eq!(got, line, "{text}: {m}");
        assert!(m.contains(needle), "{text}: {m}");
    }
}

/// Bad ASCII PLY bodies: wrong counts, non-numbers, NaN; each names its
/// line.
#[test]
fn bad_ascii_ply_bodies_name_their_line() {
    let header = "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n\
                  property float z\nelement face 1\nproperty list uchar int vertex_indices\n\
                  end_header\n";
    for (body, line, needle) in [
        (
            "0 0 0\n",
            10,
            "the file ends after 1 of the 2 'vertex' rows",
        ),
        (
            "0 0 0\n1 1 1\n",
            11,
            "the file ends after 0 of the 1 'face' rows",
        ),
        (
            "0 0 0\n1 1\n3 0 1 1\n",
            11,
            "'vertex' row 1 ends before its property 'z'",
        ),
        (
            "0 0 0 7\n",
            10,
            "'vertex' row 0 has more values than its properties take, from '7'",
        ),
        (
            "0 0 0\n1 1 1\n3 0 1\n",
            12,
            "'face' row 0 ends before its property 'vertex_indices'",
        ),
        ("0 0 0\n1 1 1\n3 0 1 1 1\n", 12, "more values"),
        (
            "0 0 0\n1 1 1\n3 0 1 1\n0 0 0\n",
            13,
            "more lines than the elements",
        ),
        (
            "0 0 0\n1 1 1\n-3 0 1 1\n",
            12,
            "the length of list 'vertex_indices'",
        ),
        ("0 0 0\n1 x 1\n3 0 1 1\n", 11, "'x' is not a number"),
        ("0 0 0\n1 1 1\n3 0 a 1\n", 12, "'a' is not a number"),
        (
            "0 0 0\nNaN 1 1\n3 0 1 1\n",
            11,
            "coordinate 'NaN' is not a finite number",
        ),
        (
            "0 0 inf\n1 1 1\n3 0 1 1\n",
            10,
            "elevation 'inf' is not a finite number",
        ),
        ("0 0 0\n1 1e300 1\n3 0 1 1\n", 11, "outside the exact range"),
    ] {
        let text = format!("{header}{body}");
        let (got, m) = parse_error(read_bytes(text.as_bytes(), None));
        assert_eq!(got, line, "{body}: {m}");
        assert!(m.contains(needle), "{body}: {m}");
    }
    // A header announcing 10¹² vertices over a short body ends with the
    // body, not in an allocation.
    let huge = "ply\nformat ascii 1.0\nelement vertex 1000000000000\nproperty double x\n\
                property double y\nend_header\n0 0\n1 0\n";
    let (line, m) = parse_error(read_bytes(huge.as_bytes(), None));
    assert_eq!(line, 8);
    assert!(
        m.contains("after 2 of the 1000000000000 'vertex' rows"),
        "{m}"
    );
}

/// Bad binary PLY bodies: truncation (checked against the announced size
/// before anything is allocated), trailing bytes, NaN and negative list
/// lengths; each names its byte offset, element, row and property.
#[test]
fn bad_binary_ply_bodies_name_their_byte() {
    let header = |vertices: u64, faces: u64| {
        format!(
            "ply\nformat binary_little_endian 1.0\nelement vertex {vertices}\n\
             property double x\nproperty double y\nelement face {faces}\n\
             property list uchar int vertex_indices\nend_header\n"
        )
        .into_bytes()
    };
    let start = header(3, 1).len();
    let body = |points: &[[f64; 2]], faces: &[&[u8]]| -> Vec<u8> {
        let mut bytes = Vec::new();
        for p in points {
            bytes.extend(p[0].to_le_bytes());
            bytes.extend(p[1].to_le_bytes());
        }
        for f in faces {
            bytes.extend(*f);
        }
        bytes
    };
    let face: Vec<u8> = [
        vec![3u8],
        0i32.to_le_bytes().to_vec(),
        1i32.to_le_bytes().to_vec(),
    ]
    .concat()
    .into_iter()
    .chain(2i32.to_le_bytes())
    .collect();
    let square = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
    let good = [header(3, 1), body(&square, &[&face])].concat();
    assert_eq!(read_bytes(&good, None).unwrap().input.points(), square);
    let cases: Vec<(Vec<u8>, String)> = vec![
        (
            good[..start + 40].to_vec(),
            format!(
                "byte {start}: the 3 'vertex' rows of 16 bytes the header announces need 48 \
                 bytes, the file has 40 left"
            ),
        ),
        (
            good[..good.len() - 2].to_vec(),
            format!(
                "byte {} ('face' row 0, property 'vertex_indices'): the file ends here: 12 \
                 more bytes needed, 10 left",
                start + 49
            ),
        ),
        (
            good[..start + 48].to_vec(),
            format!(
                "byte {} ('face' row 0, property 'vertex_indices'): the file ends here: 1 \
                 more bytes needed, 0 left",
                start + 48
            ),
        ),
        (
            [good.clone(), vec![0, 0]].concat(),
            format!(
                "byte {}: 2 bytes after the last element the header announces",
                good.len()
            ),
        ),
        (
            [
                header(3, 1),
                body(&[[0.0, 0.0], [f64::NAN, 0.0], [0.0, 1.0]], &[&face]),
            ]
            .concat(),
            format!(
                "byte {} ('vertex' row 1, property 'x'): coordinate 'NaN' is not a finite number",
                start + 16
            ),
        ),
        (
            [
                header(3, 1),
                body(&[[0.0, 0.0], [1.0, 1e300], [0.0, 1.0]], &[&face]),
            ]
            .concat(),
            format!(
                "byte {} ('vertex' row 1, property 'y'): coordinate '1000000000000000",
                start + 24
            ),
        ),
    ];
    for (bytes, needle) in cases {
        let (line, m) = parse_error(read_bytes(&bytes, None));
        assert_eq!(line, 0, "{m}");
        assert!(m.contains(&needle), "{m}\nexpected: {needle}");
    }
    // A negative list length (a signed length type).
    let signed = b"ply\nformat binary_big_endian 1.0\nelement vertex 1\nproperty float x\n\
        property float y\nelement face 1\nproperty list char int idx\nend_header\n";
    let bytes = [signed.as_slice(), &[0; 8], &[0xff]].concat();
    let (_, m) = parse_error(read_bytes(&bytes, None));
    assert!(
        m.contains(&format!(
            "byte {} ('face' row 0, property 'idx'): a list of negative length -1",
            signed.len() + 8
        )),
        "{m}"
    );
    // 10¹² announced vertices in a file of a hundred bytes: refused before
    // any allocation, for fixed rows and for rows with lists alike.
    for (vertices, faces) in [(1_000_000_000_000u64, 0), (3, 1_000_000_000_000)] {
        let bytes = [header(vertices, faces), body(&square, &[&face])].concat();
        let (_, m) = parse_error(read_bytes(&bytes, None));
        assert!(m.contains("the file"), "{m}");
    }
    let overflow = [header(u64::MAX, 0), body(&square, &[])].concat();
    let (_, m) = parse_error(read_bytes(&overflow, None));
    assert!(m.contains("need more than 2^64 bytes"), "{m}");
}

/// Bad OBJ vertices name their line.
#[test]
fn bad_obj_vertices_name_their_line() {
    for (text, line, needle) in [
        (
            "v 0 0\nv 1\n",
            2,
            "a vertex needs 'v x y [z]', found 1 value",
        ),
        ("v 0 0\nv\n", 2, "found 0 values"),
        ("v 0 0\nv 1 y\n", 2, "'y' is not a number"),
        ("v 0 0 0\nv 1 1 z\n", 2, "elevation 'z' is not a number"),
        ("v 0 0 0\nv 1 1 1 w\n", 2, "'w' is not a number"),
        ("v 0 0 0\n\nv 1 1\n", 3, "the first (line 1) has a z"),
        ("v 0 0\nv 1 1 1\n", 2, "the first (line 1) has none"),
        ("v nan 0\n", 1, "coordinate 'nan' is not a finite number"),
        ("v 0 0 -inf\n", 1, "elevation '-inf' is not a finite number"),
        ("f 1 2 3\nvt 0 0\n", 0, "no points found"),
    ] {
        let (got, m) = parse_error(read_bytes(text.as_bytes(), Some(InputFormat::Obj)));
        assert_eq!(got, line, "{text}: {m}");
        assert!(m.contains(needle), "{text}: {m}");
    }
}
