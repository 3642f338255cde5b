//! Mass properties against closed forms, parry's polygons and dense polygonal approximations.

use super::*;

fn assert_mass_close(name: &str, m: &MassProperties, r: &MassProperties, tol: f64, size: f64) {
    assert!(
        (m.mass() - r.mass()).abs() <= tol * r.mass(),
        "{name}: mass {} vs {}",
        m.mass(),
        r.mass()
    );
    assert!(
        (m.local_com - r.local_com).length() <= tol * size,
        "{name}: com {} vs {}",
        m.local_com,
        r.local_com
    );
    let (i, ir) = (m.principal_inertia(), r.principal_inertia());
    assert!((i - ir).abs() <= tol * ir, "{name}: inertia {i} vs {ir}");
}

#[test]
fn ellipse_mass_properties_match_closed_form() {
    for (a, b) in [(1.0, 1.0), (2.0, 0.5), (1.0, 1e-3)] {
        let m = Ellipse::new(a, b).mass_properties(2.5);
        let mass = 2.5 * PI * a * b;
        assert!((m.mass() - mass).abs() < 1e-14 * mass);
        assert!((m.principal_inertia() - mass * (a * a + b * b) / 4.0).abs() < 1e-14 * mass * a * a);
        assert_eq!(m.local_com, Vector::ZERO);
    }
}

#[test]
fn sharp_rounded_polygon_mass_matches_parry_convex_and_round_convex_polygon() {
    let irregular = [
        Vector::new(0.3, -0.2),
        Vector::new(2.1, 0.1),
        Vector::new(2.4, 1.3),
        Vector::new(1.0, 2.2),
    ];
    let mut polys = vec![RoundedPolygon::new(&irregular, 0.0)];
    for n in 3..10 {
        polys.push(RoundedPolygon::regular(n, 1.7, 0.0));
    }
    for p in polys {
        let ours = p.mass_properties(3.0);
        let parry = MassProperties::from_convex_polygon(3.0, p.vertices());
        assert_mass_close(
            "sharp polygon vs ConvexPolygon",
            &ours,
            &parry,
            1e-12,
            p.bounding_radius(),
        );
        let round = p.to_parry().unwrap();
        assert_mass_close(
            "sharp polygon vs RoundConvexPolygon",
            &ours,
            &round.mass_properties(3.0),
            1e-12,
            p.bounding_radius(),
        );
    }
    // parry's RoundConvexPolygon ignores the border in its mass: ours does not.
    let p = RoundedPolygon::regular(4, 1.0, 0.5);
    assert!(p.mass_properties(1.0).mass() > p.to_parry().unwrap().mass_properties(1.0).mass() + 1.0);
    // The CCD suite's rounded heptagon, as docs/rapier.md quotes it.
    let h = RoundedPolygon::regular(7, 0.4, 0.06);
    let (ours, parry) = (h.mass_properties(1.0), h.to_parry().unwrap().mass_properties(1.0));
    let three = |x: f64| format!("{x:.3}");
    assert_eq!(
        (three(ours.mass()), format!("{:.4}", ours.principal_inertia())),
        ("0.595".into(), "0.0565".into())
    );
    assert_eq!(
        (three(parry.mass()), format!("{:.4}", parry.principal_inertia())),
        ("0.438".into(), "0.0306".into())
    );
}

#[test]
fn mass_properties_match_dense_polygonal_approximation() {
    for c in cases() {
        // The chord polygon of n samples underestimates area by O(1/n²).
        let reference = MassProperties::from_convex_polygon(1.5, &c.boundary);
        let ours = c.shape.mass_properties(1.5);
        assert_mass_close(c.name, &ours, &reference, 2e-7, c.size);
    }
}

#[test]
fn custom_curve_mass_matches_the_wrapped_shapes_closed_form() {
    let e = Ellipse::new(1.3, 0.2);
    let custom = CustomCurve::new(e);
    assert_mass_close(
        "custom ellipse",
        &custom.mass_properties(2.0),
        &e.mass_properties(2.0),
        1e-13,
        1.3,
    );
    let p = RoundedPolygon::regular(6, 1.0, 0.3);
    let custom = CustomCurve::new(p.clone());
    assert_mass_close(
        "custom rounded",
        &custom.mass_properties(2.0),
        &p.mass_properties(2.0),
        1e-13,
        1.3,
    );
    let c = CapsuleEllipse::new(0.5, 1.0, 0.8);
    let custom = CustomCurve::new(c.clone());
    assert_mass_close(
        "custom capsule ellipse",
        &custom.mass_properties(2.0),
        &c.mass_properties(2.0),
        1e-13,
        1.5,
    );
    // Off-centre eccentric-anomaly ellipse: πab, centre of mass at its centre.
    let m = custom_ellipse().mass_properties(1.0);
    let (a, b) = (1.3, 0.4);
    assert!((m.mass() - PI * a * b).abs() < 1e-13);
    assert!((m.local_com - Vector::new(0.2, -0.1)).length() < 1e-13);
    assert!((m.principal_inertia() - PI * a * b * (a * a + b * b) / 4.0).abs() < 1e-13);
}
