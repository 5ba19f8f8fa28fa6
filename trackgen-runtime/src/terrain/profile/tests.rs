//! The polyline profile: the reader (round trip, every malformed file by
//! its line, no input panics), the bucket lookups against linear scans on
//! random profiles with vertical faces, the side taken at a face, and the
//! obstacles' geometry.
//!
//! Tolerances, and why:
//! * Round trip, lookups against the scans, heights against the table
//!   formula, and the gap's walls: exact (bits or `==`). The reader writes
//!   the shortest representation that reads back to the same bits, and a
//!   lookup that finds the same segment computes the same expression.
//! * Half-round: every point of every facet (sampled at 101 points) within
//!   [`HALF_ROUND_TOLERANCE`] = 0.1 mm inside the circle (the bound
//!   asked, the quantity the facet count is chosen for), and no point
//!   outside it by more than `1e-12 r` (the vertices are on the circle up
//!   to `sin_cos`'s one ulp and a rounding or two of `r sin`, `r cos`:
//!   ~1e-16 r; a vertex off the circle by a wrong formula is off by
//!   ≥ 1e-6 r).
//! * Trapezoid areas against the closed form: `1e-12` relative. The
//!   shoelace sum of a handful of products of numbers ≤ 1e3 rounds to
//!   ~1e-15 relative; a wall run off by a wrong tangent is off by ≥ 1e-3.
//! * Grade end height: exact (`z + slope · length`, one product and one
//!   sum, is what the builder computes).

use super::course::half_round_facets;
use super::*;
use std::io;

use proptest::prelude::*;
use std::path::PathBuf;

const FILE: &str = "course.csv";

fn parse(text: &str) -> Result<Profile, ProfileError> {
    Profile::from_csv_reader(text.as_bytes(), FILE)
}

/// The line and problem of a file that must fail, after checking that the
/// error names the file and that its message starts `course.csv:LINE: `.
fn parse_error(text: &[u8]) -> (usize, ParseProblem) {
    match Profile::from_csv_reader(text, FILE) {
        Err(e @ ProfileError::Parse { .. }) => {
            let message = e.to_string();
            let ProfileError::Parse {
                file,
                line,
                problem,
            } = e
            else {
                unreachable!()
            };
            assert_eq!(file, FILE);
            let prefix = format!("{FILE}:{line}: ");
            assert!(message.starts_with(&prefix), "{message}");
            println!("{message}");
            (line, problem)
        }
        other => panic!("{:?}: expected a parse error, got {other:?}", text),
    }
}

fn temp_path(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!(
        "trackgen-profile-{}-{name}.csv",
        std::process::id()
    ))
}

// ---------------------------------------------------------------- reader

#[test]
fn round_trip_through_a_file_is_bit_for_bit() {
    let mut points = vec![(-0.0, -0.0), (1e-300, 5e-324), (0.1, 0.3)];
    // A vertical face, values with long decimal expansions, large ones.
    points.extend([(0.1, -1.0 / 3.0), (2.0f64.sqrt(), 1e15 + 0.5)]);
    let mut rng = SplitMixTest(99);
    let mut x = 2.0;
    for _ in 0..500 {
        x += rng.uniform(0.0, 0.3);
        points.push((x, rng.uniform(-1e3, 1e3)));
    }
    points.push((x + 12_345.678_901_234_567, f64::MIN_POSITIVE));
    let profile = Profile::new(points.clone()).unwrap();
    let path = temp_path("round-trip");
    profile
        .write_csv(std::fs::File::create(&path).unwrap())
        .unwrap();
    let read = Profile::read_csv(&path).unwrap();
    std::fs::remove_file(&path).unwrap();
    assert_eq!(read.point_count(), points.len());
    for (i, (a, b)) in read.points().zip(points.iter()).enumerate() {
        assert_eq!(
            (a.0.to_bits(), a.1.to_bits()),
            (b.0.to_bits(), b.1.to_bits()),
            "point {i}"
        );
    }
    assert_eq!(read, profile);
}

#[test]
fn accepts_comments_blank_lines_spaces_crlf_and_a_byte_order_mark() {
    let text =
        "\u{feff}# a course\r\n\r\n  X , Z  \r\n# mid-file comment\n 0 , 0.5\t\n\n1.5e0,-2\n3,+1";
    let p = parse(text).unwrap();
    assert_eq!(
        p.points().collect::<Vec<_>>(),
        [(0.0, 0.5), (1.5, -2.0), (3.0, 1.0)]
    );
}

#[test]
fn not_a_number_names_its_line_and_column() {
    let (line, problem) = parse_error(b"x,z\n0,0\n1,abc\n");
    assert_eq!(line, 3);
    assert_eq!(
        problem,
        ParseProblem::NotANumber {
            column: "z",
            text: "abc".into()
        }
    );
    let (line, problem) = parse_error(b"x,z\n# comment\n\n ,1\n");
    assert_eq!(line, 4);
    assert_eq!(
        problem,
        ParseProblem::NotANumber {
            column: "x",
            text: String::new()
        }
    );
    // Not UTF-8: shown lossily.
    let (line, problem) = parse_error(b"x,z\n0,0\n1,\xff\n");
    assert_eq!(line, 3);
    assert!(matches!(
        problem,
        ParseProblem::NotANumber { column: "z", .. }
    ));
}

#[test]
fn wrong_field_count_names_its_line() {
    assert_eq!(
        parse_error(b"x,z\n0,0\n1,2,3\n"),
        (3, ParseProblem::FieldCount(3))
    );
    assert_eq!(
        parse_error(b"x,z\r\n0,0\r\n1\r\n"),
        (3, ParseProblem::FieldCount(1))
    );
    assert_eq!(parse_error(b"x,z\n0;0\n"), (2, ParseProblem::FieldCount(1)));
}

#[test]
fn decreasing_x_names_its_line() {
    assert_eq!(
        parse_error(b"x,z\n0,0\n2,0\n1,0\n"),
        (
            4,
            ParseProblem::Point(PointProblem::Decreasing {
                x: 1.0,
                previous: 2.0
            })
        )
    );
}

#[test]
fn nan_names_its_line() {
    let (line, problem) = parse_error(b"x,z\n0,0\nNaN,1\n");
    assert_eq!(line, 3);
    assert!(matches!(
        problem,
        ParseProblem::Point(PointProblem::NonFinite { x, z: 1.0 }) if x.is_nan()
    ));
}

#[test]
fn infinite_names_its_line() {
    assert_eq!(
        parse_error(b"x,z\n0,0\n1,inf\n"),
        (
            3,
            ParseProblem::Point(PointProblem::NonFinite {
                x: 1.0,
                z: f64::INFINITY
            })
        )
    );
    // Finite digits that overflow.
    let (line, _) = parse_error(b"x,z\n0,0\n1,0\n1e400,0\n");
    assert_eq!(line, 4);
}

#[test]
fn a_single_point_names_its_line() {
    assert_eq!(
        parse_error(b"x,z\n0,0\n\n"),
        (2, ParseProblem::TooFewPoints(1))
    );
    // No point at all: named at the header.
    assert_eq!(parse_error(b"x,z\n"), (1, ParseProblem::TooFewPoints(0)));
}

#[test]
fn no_header_names_line_one() {
    assert_eq!(
        parse_error(b"0,0\n1,1\n"),
        (1, ParseProblem::MissingHeader("0,0".into()))
    );
}

#[test]
fn a_wrong_header_names_its_line() {
    assert_eq!(
        parse_error(b"# profile\nx,y\n0,0\n1,1\n"),
        (2, ParseProblem::WrongHeader("x,y".into()))
    );
    assert_eq!(
        parse_error(b"x,z,w\n0,0\n"),
        (1, ParseProblem::WrongHeader("x,z,w".into()))
    );
}

#[test]
fn an_empty_file_names_line_one() {
    assert_eq!(parse_error(b""), (1, ParseProblem::Empty));
    assert_eq!(parse_error(b"\n\n"), (1, ParseProblem::Empty));
    // Comments only: named at the last.
    assert_eq!(parse_error(b"# a\n\n# b\n"), (3, ParseProblem::Empty));
}

#[test]
fn three_points_at_one_x_name_the_third() {
    assert_eq!(
        parse_error(b"x,z\n0,0\n1,0\n1,1\n1,2\n"),
        (5, ParseProblem::Point(PointProblem::ThirdAtOneX { x: 1.0 }))
    );
}

#[test]
fn a_repeated_point_names_its_line() {
    assert_eq!(
        parse_error(b"x,z\n0,0\n1,0\n1,0\n2,0\n"),
        (
            4,
            ParseProblem::Point(PointProblem::Repeated { x: 1.0, z: 0.0 })
        )
    );
}

#[test]
fn a_profile_of_no_length_names_its_last_point() {
    assert_eq!(
        parse_error(b"x,z\n2,0\n2,1\n"),
        (3, ParseProblem::NoLength(2.0))
    );
}

#[test]
fn a_missing_file_names_its_path() {
    let path = temp_path("missing");
    let Err(ProfileError::File { file, kind, .. }) = Profile::read_csv(&path) else {
        panic!("a missing file must be a file error");
    };
    assert_eq!(file, path.display().to_string());
    assert_eq!(kind, io::ErrorKind::NotFound);
}

/// Lines near the format: fragments that are and are not numbers, headers
/// and comments, joined by `\n` or `\r\n`.
fn near_csv() -> impl Strategy<Value = String> {
    let field = prop_oneof![
        Just(String::new()),
        Just("x".to_owned()),
        Just("z".to_owned()),
        Just("NaN".to_owned()),
        Just("-inf".to_owned()),
        Just("1e400".to_owned()),
        Just("#".to_owned()),
        (-1e3..1e3f64).prop_map(|v| v.to_string()),
        (0u32..20).prop_map(|v| v.to_string()),
        "[ -~]{0,6}",
    ];
    let line = prop::collection::vec(field, 0..4).prop_map(|f| f.join(","));
    (
        prop::collection::vec(line, 0..30),
        any::<bool>(),
        any::<bool>(),
    )
        .prop_map(|(lines, crlf, header)| {
            let sep = if crlf { "\r\n" } else { "\n" };
            let body = lines.join(sep);
            if header {
                format!("x,z{sep}{body}")
            } else {
                body
            }
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// No input panics the reader: any string, any bytes, and text near
    /// the format.
    #[test]
    fn no_string_panics_the_reader(text in ".*") {
        let _ = parse(&text);
    }

    #[test]
    fn no_bytes_panic_the_reader(bytes in prop::collection::vec(any::<u8>(), 0..512)) {
        let _ = Profile::from_csv_reader(&bytes[..], FILE);
    }

    #[test]
    fn no_near_csv_panics_the_reader(text in near_csv()) {
        if let Ok(p) = parse(&text) {
            // What it accepts is a profile: read back the same.
            let mut out = Vec::new();
            p.write_csv(&mut out).unwrap();
            prop_assert_eq!(Profile::from_csv_reader(&out[..], FILE).unwrap(), p);
        }
    }
}

// ------------------------------------------------------- lookups vs scans

/// A small integer-seeded generator for the tests' own random numbers.
struct SplitMixTest(u64);

impl SplitMixTest {
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        lo + (hi - lo) * ((z >> 11) as f64 / (1u64 << 53) as f64)
    }
}

/// Random profiles with vertical faces (never two in a row), steps from
/// 0.1 mm to 50 m so that buckets hold from none to many points.
fn random_points() -> impl Strategy<Value = Vec<(f64, f64)>> {
    let step = prop_oneof![
        3 => Just(0.0),
        1 => 1e-4..1e-3f64,
        4 => 0.01..1.0f64,
        1 => 1.0..50.0f64,
    ];
    (
        prop::collection::vec((step, -5.0..5.0f64), 1..60),
        -100.0..100.0f64,
        -5.0..5.0f64,
    )
        .prop_map(|(steps, x0, z0)| {
            let mut points = vec![(x0, z0)];
            let mut vertical = false;
            for (dx, z) in steps {
                let &(px, pz) = points.last().unwrap();
                if dx == 0.0 && !vertical {
                    // A face: of non-zero height.
                    points.push((px, if z == pz { z + 1.0 } else { z }));
                    vertical = true;
                } else {
                    points.push((px + dx.max(1e-4), z));
                    vertical = false;
                }
            }
            let &(px, pz) = points.last().unwrap();
            if px == x0 {
                points.push((px + 1.0, pz));
            }
            points
        })
}

fn scan_count_le(p: &Profile, x: f64) -> usize {
    p.xs().iter().filter(|&&xj| xj <= x).count()
}

fn scan_segment_at(p: &Profile, x: f64) -> Option<usize> {
    let c = scan_count_le(p, x);
    (c > 0 && c < p.point_count()).then(|| c - 1)
}

fn scan_segments_in(p: &Profile, x0: f64, x1: f64) -> Vec<Option<usize>> {
    let range = x0 <= x1;
    if !range {
        return Vec::new();
    }
    let (first, last) = p.x_range();
    let mut out = Vec::new();
    if x0 < first {
        out.push(None);
    }
    for i in 0..p.point_count() - 1 {
        if p.xs()[i] <= x1 && p.xs()[i + 1] >= x0 {
            out.push(Some(i));
        }
    }
    if x1 > last {
        out.push(None);
    }
    out
}

/// Convex vertices by the sign of the unnormalised cross product.
fn scan_corners_in(p: &Profile, x0: f64, x1: f64) -> Vec<usize> {
    let n = p.point_count();
    let (x, z) = (p.xs(), p.zs());
    (0..n)
        .filter(|&j| x0 <= x[j] && x[j] <= x1)
        .filter(|&j| {
            let a = if j == 0 {
                (1.0, 0.0)
            } else {
                (x[j] - x[j - 1], z[j] - z[j - 1])
            };
            let b = if j + 1 == n {
                (1.0, 0.0)
            } else {
                (x[j + 1] - x[j], z[j + 1] - z[j])
            };
            a.0 * b.1 - a.1 * b.0 < 0.0
        })
        .collect()
}

fn scan_max_height(p: &Profile, x0: f64, x1: f64) -> f64 {
    let range = x0 <= x1;
    if !range {
        return f64::NEG_INFINITY;
    }
    p.points()
        .filter(|&(x, _)| x0 <= x && x <= x1)
        .fold(p.height(x0).max(p.height(x1)), |m, (_, z)| m.max(z))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    /// Every lookup through the bucket index agrees with a linear scan,
    /// at random x, at every point's x exactly (the faces), midway between
    /// points and beyond both ends.
    #[test]
    fn lookups_agree_with_a_linear_scan(
        points in random_points(),
        extra in prop::collection::vec(-0.2..1.2f64, 0..20),
    ) {
        let p = Profile::new(points).unwrap();
        let (first, last) = p.x_range();
        let mut queries: Vec<f64> = p.xs().to_vec();
        queries.extend(p.xs().windows(2).map(|w| 0.5 * (w[0] + w[1])));
        queries.extend(extra.iter().map(|t| first + t * (last - first)));
        queries.extend([first - 1.0, last + 1.0, f64::INFINITY, f64::NEG_INFINITY]);
        for &x in &queries {
            let i = scan_segment_at(&p, x);
            prop_assert_eq!(p.segment_at(x).map(|s| s.index.unwrap()), i, "x = {}", x);
            if let Some(i) = i {
                let s = p.segment(i).unwrap();
                prop_assert!(!s.is_vertical());
                prop_assert!(s.start.0 <= x && x < s.end.0);
            }
            // The height from the scan's segment, by the same formula.
            let (h, slope) = p.height_and_slope(x);
            let (eh, es) = match i {
                Some(i) => {
                    let (a, b) = (p.point(i), p.point(i + 1));
                    let s = (b.1 - a.1) / (b.0 - a.0);
                    (a.1 + s * (x - a.0), s)
                }
                None if x < first => (p.zs()[0], 0.0),
                None => (p.zs()[p.point_count() - 1], 0.0),
            };
            prop_assert_eq!((h.to_bits(), slope.to_bits()), (eh.to_bits(), es.to_bits()));
        }
        for (k, &a) in queries.iter().enumerate() {
            let b = queries[(k * 7 + 3) % queries.len()];
            let (x0, x1) = (a.min(b), a.max(b));
            if x0.is_infinite() || x1.is_infinite() {
                continue;
            }
            let got: Vec<_> = p.segments_in(x0, x1).map(|s| s.index).collect();
            prop_assert_eq!(got, scan_segments_in(&p, x0, x1), "[{}, {}]", x0, x1);
            let got: Vec<_> = p.corners_in(x0, x1).map(|c| c.index).collect();
            prop_assert_eq!(got, scan_corners_in(&p, x0, x1), "[{}, {}]", x0, x1);
            prop_assert_eq!(
                p.max_height(x0, x1).to_bits(),
                scan_max_height(&p, x0, x1).to_bits()
            );
            // The reversed range is empty.
            if x0 < x1 {
                prop_assert_eq!(p.segments_in(x1, x0).count(), 0);
                prop_assert_eq!(p.corners_in(x1, x0).count(), 0);
                prop_assert_eq!(p.max_height(x1, x0), f64::NEG_INFINITY);
            }
        }
    }
}

#[test]
fn nan_has_no_segment_no_height_and_an_empty_range() {
    let p = Course::new().flat(1.0).unwrap().step(1.0).unwrap();
    let p = p.flat(1.0).unwrap().profile().unwrap();
    assert!(p.segment_at(f64::NAN).is_none());
    let (h, s) = p.height_and_slope(f64::NAN);
    assert!(h.is_nan() && s.is_nan());
    assert_eq!(p.segments_in(f64::NAN, 1.0).count(), 0);
    assert_eq!(p.corners_in(0.0, f64::NAN).count(), 0);
    assert_eq!(p.max_height(f64::NAN, 1.0), f64::NEG_INFINITY);
}

#[test]
fn without_faces_heights_are_the_table_formula() {
    let mut rng = SplitMixTest(5);
    let mut points = vec![(0.0, 0.0)];
    for _ in 0..300 {
        let &(x, _) = points.last().unwrap();
        points.push((x + rng.uniform(0.001, 2.0), rng.uniform(-1.0, 1.0)));
    }
    let p = Profile::new(points.clone()).unwrap();
    // The table's own lookup (a binary search over its points) as the
    // independent route to the profile's bucketed one.
    let terrain = crate::terrain::Terrain::Table(points.clone());
    let table = |x: f64| terrain.height_and_slope(x);
    for k in 0..20_000 {
        let x = -5.0 + k as f64 * 0.0173;
        if x == 0.0 {
            continue;
        }
        assert_eq!(p.height_and_slope(x), table(x), "x = {x}");
    }
    for &(x, _) in &points[1..] {
        assert_eq!(p.height_and_slope(x), table(x), "x = {x}");
    }
}

/// The largest number of points in one bucket.
fn fullest_bucket(p: &Profile) -> u32 {
    p.index
        .starts
        .windows(2)
        .map(|w| w[1] - w[0])
        .max()
        .unwrap()
}

/// On an evenly spaced course, and on an obstacle course whose short
/// facets lie among long flats, a bucket holds at most 2 points (one per
/// segment, give or take the rounding of the bucket edges): a lookup is
/// O(1).
#[test]
fn buckets_hold_few_points() {
    let even: Vec<_> = (0..=200_000)
        .map(|k| (-3.0 + k as f64 * 0.05, (k % 7) as f64))
        .collect();
    let p = Profile::new(even).unwrap();
    // One bucket per segment (span / shortest segment, rounded up).
    let buckets = p.index.starts.len() - 1;
    assert!((200_000..=200_001).contains(&buckets), "{buckets}");
    assert!(fullest_bucket(&p) <= 2, "{}", fullest_bucket(&p));
    let course = Obstacle::HalfRound { radius: 0.762 }
        .course(50.0, 50.0)
        .unwrap();
    println!(
        "half-round of 30 in among 50 m flats: {} points, {} buckets, fullest {}",
        course.point_count(),
        course.index.starts.len() - 1,
        fullest_bucket(&course)
    );
    assert!(fullest_bucket(&course) <= 2);
}

// ------------------------------------------------------ faces and corners

/// A step up, a step down and a gap: at a face's x the right-hand side.
#[test]
fn at_a_face_the_surface_to_the_right() {
    let p = Course::new()
        .flat(2.0)
        .and_then(|c| c.step(0.5))
        .and_then(|c| c.flat(2.0))
        .and_then(|c| c.step(-0.5))
        .and_then(|c| c.flat(2.0))
        .and_then(|c| c.profile())
        .unwrap();
    // Points: (0,0) (2,0) (2,0.5) (4,0.5) (4,0) (6,0).
    assert_eq!(p.point_count(), 6);
    // Step up at 2: the top it climbs; step down at 4: the bottom.
    assert_eq!(p.height_and_slope(2.0), (0.5, 0.0));
    assert_eq!(p.segment_at(2.0).unwrap().index, Some(2));
    assert_eq!(p.height(2.0 - 1e-12), 0.0);
    assert_eq!(p.height_and_slope(4.0), (0.0, 0.0));
    assert_eq!(p.segment_at(4.0).unwrap().index, Some(4));
    assert_eq!(p.height(4.0 - 1e-12), 0.5);
    // Both faces are segments; the top edges are the convex corners.
    let faces: Vec<_> = p
        .segments_in(0.0, 6.0)
        .filter(Segment::is_vertical)
        .collect();
    assert_eq!(faces.len(), 2);
    assert_eq!(faces[0].direction(), (0.0, 1.0));
    assert_eq!(faces[1].direction(), (0.0, -1.0));
    let corners: Vec<_> = p.corners_in(-1.0, 7.0).collect();
    assert_eq!(
        corners.iter().map(|c| c.point).collect::<Vec<_>>(),
        [(2.0, 0.5), (4.0, 0.5)]
    );
    for c in &corners {
        assert_eq!((c.turn_sin(), c.turn_cos()), (1.0, 0.0), "a right angle");
    }
    // A range ending exactly at a face holds both of its points.
    assert_eq!(p.max_height(0.0, 2.0), 0.5);
    assert_eq!(p.max_height(4.0, 6.0), 0.5);
    assert_eq!(p.max_height(4.5, 6.0), 0.0);
}

#[test]
fn segments_in_a_range_beyond_the_ends_include_the_flat_extensions() {
    let p = Course::starting_at(10.0, 1.0)
        .and_then(|c| c.grade(0.5, 2.0))
        .and_then(|c| c.profile())
        .unwrap();
    let s: Vec<_> = p.segments_in(8.0, 13.0).collect();
    assert_eq!(
        s,
        [
            Segment {
                index: None,
                start: (8.0, 1.0),
                end: (10.0, 1.0)
            },
            Segment {
                index: Some(0),
                start: (10.0, 1.0),
                end: (12.0, 2.0)
            },
            Segment {
                index: None,
                start: (12.0, 2.0),
                end: (13.0, 2.0)
            },
        ]
    );
    // Entirely beyond the end: the extension alone.
    let s: Vec<_> = p.segments_in(20.0, 21.0).collect();
    assert_eq!(s.len(), 1);
    assert_eq!((s[0].start, s[0].end), ((12.0, 2.0), (21.0, 2.0)));
    // The last point, where the grade meets the flat, is a convex corner.
    let c: Vec<_> = p.corners_in(0.0, 20.0).map(|c| c.index).collect();
    assert_eq!(c, [1]);
}

// ------------------------------------------------------------- obstacles

#[test]
fn half_round_crest_within_a_tenth_of_a_millimetre_of_the_circle() {
    let inch = 0.0254;
    let mut radii: Vec<f64> = (1..=15).map(|k| 2.0 * k as f64 * inch).collect();
    radii.extend([1e-3, 0.01, 1.0, 10.0, 100.0]);
    let mut worst: f64 = 0.0;
    for r in radii {
        let p = Course::new()
            .flat(1.0)
            .and_then(|c| c.half_round(r))
            .and_then(|c| c.flat(1.0))
            .and_then(|c| c.profile())
            .unwrap();
        let (cx, n) = (1.0 + r, p.point_count() - 3);
        assert_eq!(n % 2, 0, "r = {r}: an even facet count");
        assert_eq!(n, half_round_facets(r));
        // The feet and the crest exactly.
        assert_eq!(p.point(1), (1.0, 0.0));
        assert_eq!(p.point(1 + n / 2), (cx, r));
        assert_eq!(p.point(1 + n), (cx + r, 0.0));
        for i in 1..=n {
            let s = p.segment(i).unwrap();
            for k in 0..=100 {
                let t = k as f64 / 100.0;
                let x = s.start.0 + t * (s.end.0 - s.start.0);
                let z = s.start.1 + t * (s.end.1 - s.start.1);
                let d = ((x - cx) * (x - cx) + z * z).sqrt();
                assert!(
                    d <= r * (1.0 + 1e-12) && r - d <= HALF_ROUND_TOLERANCE,
                    "r = {r}, facet {i}: distance {d}"
                );
                worst = worst.max(r - d);
            }
        }
        // Every vertex over the crest is a convex corner; the feet are not.
        let corners: Vec<_> = p.corners_in(1.0, 1.0 + 2.0 * r).map(|c| c.index).collect();
        assert_eq!(corners, (2..=n).collect::<Vec<_>>(), "r = {r}");
    }
    println!("half-round: deepest facet point {worst:e} m inside the circle (bound 1e-4)");
}

/// The polygon's area between the profile from `from` to `to` and the
/// straight line joining them (positive above), by the shoelace formula.
fn area_above_chord(p: &Profile, from: usize, to: usize) -> f64 {
    let mut twice = 0.0;
    for i in from..to {
        let (a, b) = (p.point(i), p.point(i + 1));
        twice += a.0 * b.1 - b.0 * a.1;
    }
    let (a, b) = (p.point(to), p.point(from));
    twice += a.0 * b.1 - b.0 * a.1;
    -twice / 2.0
}

#[test]
fn trapezoid_areas_equal_the_closed_form() {
    let mut worst: f64 = 0.0;
    for angle in [90.0, 75.0, 60.0, 45.0, 30.0, 10.0, 1.0] {
        for (h, w) in [(0.5, 1.0), (2.0, 0.3), (1.2, 4.0)] {
            let run = if angle == 90.0 {
                0.0
            } else {
                h / (angle * std::f64::consts::PI / 180.0).tan()
            };
            let closed = h * (w + run);
            let ditch = Course::starting_at(3.0, 1.0)
                .and_then(|c| c.flat(5.0))
                .and_then(|c| c.ditch(h, w, angle))
                .and_then(|c| c.flat(5.0))
                .and_then(|c| c.profile())
                .unwrap();
            let barrier = Course::starting_at(3.0, 1.0)
                .and_then(|c| c.flat(5.0))
                .and_then(|c| c.barrier(h, w, angle))
                .and_then(|c| c.flat(5.0))
                .and_then(|c| c.profile())
                .unwrap();
            let last = ditch.point_count() - 2;
            let (d, b) = (
                -area_above_chord(&ditch, 1, last),
                area_above_chord(&barrier, 1, last),
            );
            for (area, name) in [(d, "ditch"), (b, "barrier")] {
                let e = (area - closed).abs() / closed;
                worst = worst.max(e);
                assert!(
                    e <= 1e-12,
                    "{name} {h} × {w} at {angle}°: {area} vs {closed}"
                );
            }
            // Top width of the ditch, bottom of the barrier.
            let top = ditch.point(last).0 - ditch.point(1).0;
            assert!((top - (w + 2.0 * run)).abs() <= 1e-12 * top);
            // Vertical walls at 90°.
            assert_eq!(ditch.segment(1).unwrap().is_vertical(), angle == 90.0);
            assert_eq!(barrier.segment(3).unwrap().is_vertical(), angle == 90.0);
        }
    }
    println!("trapezoid areas: worst relative error {worst:e} (bound 1e-12)");
}

#[test]
fn a_gap_has_vertical_walls_and_its_lips_are_corners() {
    let p = Obstacle::Gap {
        width: 2.0,
        depth: 3.0,
    }
    .course(5.0, 5.0)
    .unwrap();
    assert_eq!(
        p.points().collect::<Vec<_>>(),
        [
            (0.0, 0.0),
            (5.0, 0.0),
            (5.0, -3.0),
            (7.0, -3.0),
            (7.0, 0.0),
            (12.0, 0.0)
        ]
    );
    assert!(p.segment(1).unwrap().is_vertical() && p.segment(3).unwrap().is_vertical());
    let lips: Vec<_> = p.corners_in(0.0, 12.0).map(|c| c.point).collect();
    assert_eq!(lips, [(5.0, 0.0), (7.0, 0.0)]);
    // At the near wall's x, the bottom; at the far wall's, the far lip.
    assert_eq!(p.height(5.0), -3.0);
    assert_eq!(p.height(7.0), 0.0);
}

#[test]
fn steps_grades_and_merged_faces() {
    let up = Obstacle::Step { height: 0.3 }.course(1.0, 1.0).unwrap();
    assert_eq!(
        up.points().collect::<Vec<_>>(),
        [(0.0, 0.0), (1.0, 0.0), (1.0, 0.3), (2.0, 0.3)]
    );
    let down = Obstacle::Step { height: -0.3 }.course(1.0, 1.0).unwrap();
    assert_eq!(down.point(3), (2.0, -0.3));
    let grade = Obstacle::Grade {
        slope: 0.6,
        length: 7.0,
    }
    .course(2.0, 3.0)
    .unwrap();
    assert_eq!(grade.point(2), (9.0, 0.6 * 7.0));
    assert_eq!(grade.point(3), (12.0, 0.6 * 7.0));
    // A step then a gap at one x: one face from the step's foot to the
    // gap's bottom; a step and its opposite: no face.
    let p = Course::new()
        .flat(1.0)
        .and_then(|c| c.step(0.5))
        .and_then(|c| c.gap(1.0, 2.0))
        .and_then(|c| c.flat(1.0))
        .and_then(|c| c.profile())
        .unwrap();
    assert_eq!(
        p.points().collect::<Vec<_>>(),
        [
            (0.0, 0.0),
            (1.0, 0.0),
            (1.0, -1.5),
            (2.0, -1.5),
            (2.0, 0.5),
            (3.0, 0.5)
        ]
    );
    let p = Course::new()
        .flat(1.0)
        .and_then(|c| c.step(0.5))
        .and_then(|c| c.step(-0.5))
        .and_then(|c| c.flat(1.0))
        .and_then(|c| c.profile())
        .unwrap();
    assert_eq!(
        p.points().collect::<Vec<_>>(),
        [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0)]
    );
}

#[test]
fn parameters_out_of_range_name_themselves_and_their_range() {
    let cases: Vec<(Result<Course, ProfileError>, &str, &str, &str)> = vec![
        (
            Course::new().flat(0.0),
            "flat",
            "length",
            "0 < length ≤ 1e5 m",
        ),
        (
            Course::new().flat(f64::NAN),
            "flat",
            "length",
            "0 < length ≤ 1e5 m",
        ),
        (
            Course::new().half_round(-1.0),
            "half-round",
            "radius",
            "0 < radius ≤ 100 m",
        ),
        (
            Course::new().half_round(101.0),
            "half-round",
            "radius",
            "0 < radius ≤ 100 m",
        ),
        (
            Course::new().step(0.0),
            "step",
            "height",
            "0 < |height| ≤ 100 m",
        ),
        (
            Course::new().gap(0.0, 1.0),
            "gap",
            "width",
            "0 < width ≤ 1e5 m",
        ),
        (
            Course::new().gap(1.0, f64::INFINITY),
            "gap",
            "depth",
            "0 < depth ≤ 100 m",
        ),
        (
            Course::new().ditch(-1.0, 1.0, 45.0),
            "ditch",
            "depth",
            "0 < depth ≤ 100 m",
        ),
        (
            Course::new().ditch(1.0, 0.0, 45.0),
            "ditch",
            "bottom_width",
            "0 < bottom_width ≤ 1e5 m",
        ),
        (
            Course::new().ditch(1.0, 1.0, 90.5),
            "ditch",
            "wall_angle",
            "0 < wall_angle ≤ 90 degrees",
        ),
        (
            Course::new().barrier(1.0, 1.0, 0.0),
            "barrier",
            "wall_angle",
            "0 < wall_angle ≤ 90 degrees",
        ),
        (
            Course::new().barrier(1.0, -2.0, 30.0),
            "barrier",
            "top_width",
            "0 < top_width ≤ 1e5 m",
        ),
        (
            Course::new().barrier(200.0, 1.0, 30.0),
            "barrier",
            "height",
            "0 < height ≤ 100 m",
        ),
        (
            Course::new().grade(11.0, 1.0),
            "grade",
            "slope",
            "|slope| ≤ 10 (rise over run)",
        ),
        (
            Course::new().grade(0.1, 0.0),
            "grade",
            "length",
            "0 < length ≤ 1e5 m",
        ),
        (
            Course::starting_at(f64::NAN, 0.0),
            "course",
            "start x",
            "|x| ≤ 1e6 m",
        ),
    ];
    for (result, shape, parameter, allowed) in cases {
        let e = result.unwrap_err();
        let message = e.to_string();
        let ProfileError::Parameter {
            shape: s,
            parameter: p,
            allowed: a,
            ..
        } = e
        else {
            panic!("{message}");
        };
        assert_eq!((s, p, a), (shape, parameter, allowed), "{message}");
        assert!(message.contains(parameter) && message.contains(allowed));
    }
    // A course of one face spans no length.
    assert_eq!(
        Course::new().step(1.0).unwrap().profile(),
        Err(ProfileError::NoLength(0.0))
    );
}

#[test]
fn new_checks_every_invariant_by_index() {
    use PointProblem::*;
    let point = |index, problem| Err(ProfileError::Point { index, problem });
    assert_eq!(Profile::new(vec![]), Err(ProfileError::TooFewPoints(0)));
    assert_eq!(
        Profile::new(vec![(0.0, 0.0)]),
        Err(ProfileError::TooFewPoints(1))
    );
    assert_eq!(
        Profile::new(vec![(0.0, 0.0), (1.0, f64::NAN)]).map_err(|e| e.to_string()),
        Err("profile point 1: x = 1 m, z = NaN m: not finite".to_owned())
    );
    assert_eq!(
        Profile::new(vec![(0.0, 0.0), (-1.0, 0.0)]),
        point(
            1,
            Decreasing {
                x: -1.0,
                previous: 0.0
            }
        )
    );
    assert_eq!(
        Profile::new(vec![(0.0, 0.0), (0.0, 1.0), (0.0, 2.0)]),
        point(2, ThirdAtOneX { x: 0.0 })
    );
    assert_eq!(
        Profile::new(vec![(0.0, 0.0), (1.0, 0.0), (1.0, 0.0)]),
        point(2, Repeated { x: 1.0, z: 0.0 })
    );
    assert_eq!(
        Profile::new(vec![(3.0, 0.0), (3.0, 1.0)]),
        Err(ProfileError::NoLength(3.0))
    );
}
