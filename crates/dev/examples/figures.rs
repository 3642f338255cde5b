//! Writes the specification's figures, computed from the crate's own functions, as PNG and SVG
//! files into a folder (default `target/figures`).
//!
//! Run: `cargo run --release --example figures -- [DIR]` (from the workspace's root; the example
//! belongs to the dev-only member `crates/dev`, whose dependencies draw the figures)
//!
//! Pure Rust: plotters draws the bitmaps and the SVG files; text uses DejaVu Sans (Bitstream
//! Vera licence) embedded by the `dejavu` crate, so no system font library is needed.
//!
//! * `fig1_shapes`: the ellipse a = 1, b = 2, the same moved by C = (1, 2) and rotated by 0.5,
//!   the regular heptagon with rounded corners, and shape1 of Appendix A with its pieces coloured.
//! * `fig2_transform`: the pair of the specification in the world, translated so that object2
//!   is at the origin, and rotated into object2's local space.
//! * `fig3_distances`: distanceEuclidean, −distanceFwd and distanceSide of that pair over φ, with
//!   the global extremum found by `stationary_distance`.
//! * `fig4_moving`: a moving version of that pair: the shapes at several times, and
//!   distanceSide(φ, t), distanceFwd(φ, t) with the zero level of distanceSide and the path
//!   tracked by `time_of_impact_traced`.
//! * `fig5_appendix_c`: distanceEuclidean over φ for ellipse pairs of axis ratios 1:5, 1:15 and
//!   1:100, with the basin of the global minimum shaded, against eq. 1's parameter and against the
//!   crate's normal angle.
//! * `fig6_appendix_d`: the heptagon spinning at 30 rad/s against an ellipse: the shapes up to the
//!   impact and distanceSide(φ, t) with the tracked path.

#[path = "../../../examples/common/mod.rs"]
mod common;
#[path = "figures/drawing.rs"]
mod drawing;
#[path = "figures/figures_1_to_3.rs"]
mod figures_1_to_3;
#[path = "figures/figures_4_to_6.rs"]
mod figures_4_to_6;

use drawing::*;
use figures_1_to_3::*;
use figures_4_to_6::*;

use common::appendix_d;
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::NonlinearRigidMotion;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use smooth_ccd2d::method::{eval_pair, PairFrame};
use smooth_ccd2d::{
    stationary_distance, time_of_impact_traced, CapsuleEllipse, ConvexCurve, DistanceOptions, Ellipse, RoundedPolygon,
    ToiOptions, ToiStatus, TraceEvent,
};
use std::error::Error;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

type Res<T = ()> = Result<T, Box<dyn Error>>;
type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

const FONT: &str = "sans-serif";
const OBJ1: RGBColor = RGBColor(31, 119, 180);
const OBJ2: RGBColor = RGBColor(214, 39, 40);
const GREEN: RGBColor = RGBColor(44, 160, 44);
const ORANGE: RGBColor = RGBColor(255, 127, 14);
const PURPLE: RGBColor = RGBColor(148, 103, 189);
const GREY: RGBColor = RGBColor(120, 120, 120);
const PATH: RGBColor = RGBColor(0, 200, 0);
const GOLD: RGBColor = RGBColor(255, 215, 0);

fn main() {
    let dir = std::env::args_os()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("target/figures"));
    let start = std::time::Instant::now();
    match write_all(&dir) {
        Ok(files) => {
            for f in &files {
                let len = std::fs::metadata(f).map(|m| m.len()).unwrap_or(0);
                println!("{:>10} bytes  {}", len, f.display());
            }
            println!("{} files in {:.2} s", files.len(), start.elapsed().as_secs_f64());
        }
        Err(e) => {
            eprintln!("figures: {e}");
            std::process::exit(1);
        }
    }
}

/// Writes every figure as `<name>.png` and `<name>.svg` into `dir` (created if missing) and
/// returns the paths written.
pub fn write_all(dir: &Path) -> Res<Vec<PathBuf>> {
    register_font()?;
    std::fs::create_dir_all(dir)?;
    let mut out = Vec::new();
    emit(dir, &Fig1, &mut out)?;
    emit(dir, &Fig2::new()?, &mut out)?;
    emit(dir, &Fig3::new()?, &mut out)?;
    emit(dir, &Fig4::new()?, &mut out)?;
    emit(dir, &Fig5::new()?, &mut out)?;
    emit(dir, &Fig6::new()?, &mut out)?;
    Ok(out)
}

fn register_font() -> Res {
    static ONCE: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    let ok = *ONCE.get_or_init(|| {
        plotters::style::register_font(FONT, FontStyle::Normal, dejavu::sans::regular()).is_ok()
            && plotters::style::register_font(FONT, FontStyle::Bold, dejavu::sans::bold()).is_ok()
    });
    if ok {
        Ok(())
    } else {
        Err("could not load the embedded DejaVu Sans font".into())
    }
}

/// A figure: data computed once, drawn on any backend.
trait Figure {
    fn name(&self) -> &'static str;
    fn size(&self) -> (u32, u32);
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Res
    where
        DB::ErrorType: 'static;
}

fn emit<F: Figure>(dir: &Path, fig: &F, out: &mut Vec<PathBuf>) -> Res {
    let png = dir.join(format!("{}.png", fig.name()));
    {
        let root = BitMapBackend::new(&png, fig.size()).into_drawing_area();
        root.fill(&WHITE)?;
        fig.draw(&root)?;
        root.present()?;
    }
    out.push(png);
    let svg = dir.join(format!("{}.svg", fig.name()));
    {
        let root = SVGBackend::new(&svg, fig.size()).into_drawing_area();
        root.fill(&WHITE)?;
        fig.draw(&root)?;
        root.present()?;
    }
    out.push(svg);
    Ok(())
}
