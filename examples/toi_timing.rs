//! Times `time_of_impact` on the 200 ellipse – ellipse and ellipse – disc scenarios of
//! `tests/common` (seeds 0..200): each scenario repeated 100 times, the minimum over 7 rounds,
//! then the median and p90 over hits and over misses, with the median evaluations and mean
//! predictor steps. The direct harness the README's time-of-impact notes quote; `DISP=1` times
//! the same queries through `SmoothDispatcher::cast_shapes_nonlinear` (parry `Ball` for the
//! disc), `LIST=1` prints the hits around the median.
//!
//! `cargo run --release --example toi_timing`
#[path = "common/mod.rs"]
mod common;
use common::scenarios::{generate, Scenario, ScenarioClass, TestShape};
use smooth_ccd2d::{time_of_impact, ToiOptions, ToiStatus};
use std::time::Instant;

fn main() {
    let opts = ToiOptions::default();
    for (name, class) in [
        ("ee", ScenarioClass::EllipseEllipse),
        ("eb", ScenarioClass::EllipseBall),
    ] {
        let sc: Vec<_> = (0..200).map(|s| generate(class, s)).collect();
        let run = |s: &Scenario| {
            match (&s.shape1, &s.shape2) {
                (TestShape::Ellipse(a), TestShape::Ellipse(b)) => {
                    time_of_impact(a, &s.motion1, b, &s.motion2, s.t0, s.t1, &opts)
                }
                (TestShape::Ellipse(a), TestShape::Ball(b)) => {
                    time_of_impact(a, &s.motion1, b, &s.motion2, s.t0, s.t1, &opts)
                }
                _ => unreachable!(),
            }
            .unwrap()
        };
        let d = smooth_ccd2d::SmoothDispatcher::default();
        let shapes: Vec<(Box<dyn parry2d_f64::shape::Shape>, Box<dyn parry2d_f64::shape::Shape>)> = sc
            .iter()
            .map(|s| (s.shape1.parry_shape(), s.shape2.parry_shape()))
            .collect();
        let disp = std::env::var("DISP").is_ok();
        let mut best = vec![f64::INFINITY; sc.len()];
        for _round in 0..7 {
            for (i, s) in sc.iter().enumerate() {
                let reps = 100;
                let st = Instant::now();
                if disp {
                    use parry2d_f64::query::QueryDispatcher;
                    let (g1, g2) = &shapes[i];
                    for _ in 0..reps {
                        std::hint::black_box(
                            d.cast_shapes_nonlinear(&s.motion1, &**g1, &s.motion2, &**g2, s.t0, s.t1, true)
                                .ok(),
                        );
                    }
                } else {
                    for _ in 0..reps {
                        std::hint::black_box(run(std::hint::black_box(s)));
                    }
                }
                best[i] = best[i].min(st.elapsed().as_secs_f64() / reps as f64);
            }
        }
        for want_hit in [true, false] {
            let mut a = vec![];
            let (mut ev, mut st, mut n) = (vec![], 0usize, 0usize);
            for (i, s) in sc.iter().enumerate() {
                let r = run(s);
                if (r.status == ToiStatus::Hit) == want_hit {
                    a.push(best[i]);
                    ev.push(r.cost.evaluations);
                    st += r.cost.predictor_steps;
                    n += 1;
                }
            }
            if std::env::var("LIST").is_ok() && want_hit {
                let mut l: Vec<(f64, usize, usize)> = vec![];
                for (i, s) in sc.iter().enumerate() {
                    let r = run(s);
                    if r.status == ToiStatus::Hit {
                        l.push((best[i] * 1e6, i, r.cost.evaluations));
                    }
                }
                l.sort_by(|x, y| x.0.partial_cmp(&y.0).unwrap());
                for (k, (t, i, e)) in l.iter().enumerate() {
                    if k + 12 >= l.len() / 2 && k <= l.len() / 2 + 12 {
                        println!("  {k} {t:.3} seed {i} {:?} evals {e}", sc[*i].kind);
                    }
                }
            }
            a.sort_by(|x, y| x.partial_cmp(y).unwrap());
            ev.sort();
            println!(
                "{name} {}: n {n} median {:.3} us p90 {:.2}; evals median {} mean {:.1}; steps mean {:.1}",
                if want_hit { "hit " } else { "miss" },
                a[n / 2] * 1e6,
                a[n * 9 / 10] * 1e6,
                ev[n / 2],
                ev.iter().sum::<usize>() as f64 / n as f64,
                st as f64 / n as f64
            );
        }
    }
}
