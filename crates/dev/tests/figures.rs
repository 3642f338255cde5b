//! Runs the `figures` example's code into a temporary folder and checks every file: present,
//! non-empty, PNGs decodable and not a single flat colour, SVGs well begun and ended.

#[path = "../examples/figures.rs"]
#[allow(dead_code)]
mod figures;

use std::collections::HashSet;

#[test]
fn figures_are_written_and_not_blank() {
    let dir = std::env::temp_dir().join(format!("smooth_ccd2d_figures_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let start = std::time::Instant::now();
    let files = figures::write_all(&dir).expect("figures are written");
    let elapsed = start.elapsed().as_secs_f64();
    assert_eq!(files.len(), 12, "six figures, each as PNG and SVG");
    for f in &files {
        let len = std::fs::metadata(f)
            .unwrap_or_else(|e| panic!("{}: {e}", f.display()))
            .len();
        assert!(len > 1000, "{} is nearly empty ({len} bytes)", f.display());
        match f.extension().and_then(|e| e.to_str()) {
            Some("png") => {
                let img = image::open(f)
                    .unwrap_or_else(|e| panic!("{}: {e}", f.display()))
                    .to_rgb8();
                let colours: HashSet<[u8; 3]> = img.pixels().map(|p| p.0).collect();
                assert!(
                    colours.len() >= 16,
                    "{} has only {} colours",
                    f.display(),
                    colours.len()
                );
                println!(
                    "{len:>10} bytes  {}x{}  {} colours  {}",
                    img.width(),
                    img.height(),
                    colours.len(),
                    f.display()
                );
            }
            Some("svg") => {
                let text = std::fs::read_to_string(f).expect("SVG is UTF-8");
                assert!(
                    text.contains("<svg") && text.trim_end().ends_with("</svg>"),
                    "{} is not a whole SVG",
                    f.display()
                );
                assert!(text.contains("<text"), "{} has no text", f.display());
                println!("{len:>10} bytes  {}", f.display());
            }
            _ => panic!("unexpected file {}", f.display()),
        }
    }
    println!("{} files in {elapsed:.2} s", files.len());
    std::fs::remove_dir_all(&dir).expect("temporary folder removed");
}
