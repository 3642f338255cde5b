//! The examples' drawing helpers: the output folder, shape outlines and a hand-written SVG
//! writer (no drawing crate: the examples build only the crate, parry and rapier).
use rapier2d_f64::prelude::*;
use std::fmt::Write as _;
use std::path::PathBuf;

/// The output folder: the first command-line argument, or `target/examples-out` under the crate's
/// root (wherever the example is run from); created.
pub fn out_dir() -> PathBuf {
    // A flag (`--help`, a mistyped option) is not a folder: say what the example takes.
    if let Some(flag) = std::env::args().nth(1).filter(|a| a.starts_with('-')) {
        let name = std::env::args().next().unwrap_or_default();
        let name = std::path::Path::new(&name)
            .file_name()
            .map_or(name.clone(), |n| n.to_string_lossy().into_owned());
        eprintln!(
            "usage: cargo run --release --example {name} [-- OUTPUT_FOLDER]\n\
             (the SVG goes to OUTPUT_FOLDER, by default target/examples-out under the crate; `{flag}` is not a folder)"
        );
        std::process::exit(if flag == "--help" || flag == "-h" { 0 } else { 2 });
    }
    let dir = std::env::args().nth(1).map_or_else(
        || {
            PathBuf::from(env!("CARGO_MANIFEST_DIR"))
                .join("target")
                .join("examples-out")
        },
        PathBuf::from,
    );
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("cannot create {}: {e}", dir.display()));
    dir
}

/// The outline of a convex shape at `pose` (world frame): its support points in `n` directions.
pub fn outline(shape: &dyn Shape, pose: &Pose, n: usize) -> Vec<Vector> {
    let sm = shape.as_support_map().expect("a convex shape with a support map");
    (0..n)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            sm.support_point(pose, Vector::new(a.cos(), a.sin()))
        })
        .collect()
}

/// The world x of the shape's point furthest along +x.
pub fn max_x(shape: &dyn Shape, pose: &Pose) -> f64 {
    shape
        .as_support_map()
        .expect("a support map")
        .support_point(pose, Vector::X)
        .x
}

/// A rectangle of an SVG picture showing the world window `[x0, x1] × [y0, y1]` (y up).
#[derive(Clone, Copy, Debug)]
pub struct Panel {
    pub px: f64,
    pub py: f64,
    pub width: f64,
    pub height: f64,
    pub x0: f64,
    pub x1: f64,
    pub y0: f64,
    pub y1: f64,
}

impl Panel {
    /// A panel whose height follows the window's aspect ratio.
    pub fn fit(px: f64, py: f64, width: f64, x0: f64, x1: f64, y0: f64, y1: f64) -> Self {
        Panel {
            px,
            py,
            width,
            height: width * (y1 - y0) / (x1 - x0),
            x0,
            x1,
            y0,
            y1,
        }
    }

    pub fn map(&self, x: f64, y: f64) -> (f64, f64) {
        (
            self.px + (x - self.x0) / (self.x1 - self.x0) * self.width,
            self.py + (self.y1 - y) / (self.y1 - self.y0) * self.height,
        )
    }
}

/// A hand-written SVG document.
pub struct Svg {
    width: f64,
    height: f64,
    body: String,
    clips: usize,
}

impl Svg {
    pub fn new(width: f64, height: f64) -> Self {
        Svg {
            width,
            height,
            body: String::new(),
            clips: 0,
        }
    }

    /// Starts a group clipped to the panel (close it with [`Svg::end_panel`]) and frames it.
    pub fn begin_panel(&mut self, p: &Panel, title: &str) {
        self.clips += 1;
        let id = self.clips;
        let _ = writeln!(
            self.body,
            r#"<clipPath id="c{id}"><rect x="{:.2}" y="{:.2}" width="{:.2}" height="{:.2}"/></clipPath>"#,
            p.px, p.py, p.width, p.height
        );
        let _ = writeln!(
            self.body,
            r##"<rect x="{:.2}" y="{:.2}" width="{:.2}" height="{:.2}" fill="#fcfcfc" stroke="#888" stroke-width="0.8"/>"##,
            p.px, p.py, p.width, p.height
        );
        self.text(p.px + 4.0, p.py - 5.0, 13.0, title);
        let _ = writeln!(self.body, r#"<g clip-path="url(#c{id})">"#);
    }

    pub fn end_panel(&mut self) {
        self.body.push_str("</g>\n");
    }

    /// A polyline (closed: a polygon) through world points.
    pub fn polyline(&mut self, p: &Panel, pts: &[Vector], closed: bool, stroke: &str, width: f64, fill: &str) {
        if pts.is_empty() {
            return;
        }
        let tag = if closed { "polygon" } else { "polyline" };
        let _ = write!(self.body, r#"<{tag} points=""#);
        for q in pts {
            let (x, y) = p.map(q.x, q.y);
            let _ = write!(self.body, "{x:.2},{y:.2} ");
        }
        let _ = writeln!(
            self.body,
            r#"" fill="{fill}" stroke="{stroke}" stroke-width="{width}" stroke-linejoin="round"/>"#
        );
    }

    pub fn circle(&mut self, p: &Panel, c: Vector, radius_px: f64, fill: &str) {
        let (x, y) = p.map(c.x, c.y);
        let _ = writeln!(
            self.body,
            r#"<circle cx="{x:.2}" cy="{y:.2}" r="{radius_px}" fill="{fill}"/>"#
        );
    }

    /// Text at pixel coordinates.
    pub fn text(&mut self, x: f64, y: f64, size: f64, s: &str) {
        let s = s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;");
        let _ = writeln!(
            self.body,
            r#"<text x="{x:.2}" y="{y:.2}" font-family="sans-serif" font-size="{size}">{s}</text>"#
        );
    }

    pub fn save(&self, path: &std::path::Path) {
        let doc = format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\">\n\
             <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n{}</svg>\n",
            self.body,
            w = self.width,
            h = self.height
        );
        std::fs::write(path, doc).unwrap_or_else(|e| panic!("cannot write {}: {e}", path.display()));
    }
}
