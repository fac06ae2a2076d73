use super::*;

/// A smooth test surface's samples: slice i at u_i, sample j.
fn data(u: &[f64], m: usize) -> (Vec<Vec<f64>>, Vec<Vec<f64>>) {
    let y = u
        .iter()
        .map(|&x| (0..m).map(|j| j as f64 * (1.0 + 0.01 * x) + 0.1 * (0.3 * j as f64).sin()).collect())
        .collect();
    let z = u.iter().map(|&x| (0..m).map(|j| (0.2 * j as f64 + 0.05 * x).cos() + 0.001 * x * x).collect()).collect();
    (y, z)
}

/// Without interruptions the masked surface is the tensor not-a-knot spline: along the track
/// each sample's path, across the track the samples' spline over their indices.
#[test]
fn a_full_mask_is_the_tensor_not_a_knot_spline() {
    let u = [0.0, 1.0, 2.5, 3.0, 4.5, 6.0, 7.0];
    let m = 9;
    let (y, z) = data(&u, m);
    let s = Masked::new(&u, &y, &z, &vec![(0, m - 1); u.len()]).unwrap();
    let along = NotAKnot::new(&u).unwrap();
    let sites: Vec<f64> = (0..m).map(|j| j as f64).collect();
    let across = NotAKnot::new(&sites).unwrap();
    for x in [-1.0, 0.0, 0.3, 2.5, 2.7, 5.0, 7.0, 9.0] {
        let w = along.weights(x);
        let at = |d: &[Vec<f64>], j: usize| w.iter().zip(d).map(|(w, r)| w * r[j]).sum::<f64>();
        for (j, sample) in s.samples_at(x).into_iter().enumerate() {
            let (yy, zz) = sample.unwrap();
            assert!((yy - at(&y, j)).abs() < 1e-12 && (zz - at(&z, j)).abs() < 1e-12, "u {x}, j {j}");
        }
        let ys: Vec<f64> = (0..m).map(|j| at(&y, j)).collect();
        let zs: Vec<f64> = (0..m).map(|j| at(&z, j)).collect();
        let (cy, cz) = (across.curve(&ys), across.curve(&zs));
        let v = 3.4;
        let k = 3;
        let (yv, zv) = (cy.value_on(k, v - 3.0), cz.value_on(k, v - 3.0));
        let found = s.z_at(x, yv, first_root_test).unwrap();
        assert!((found - zv).abs() < 1e-9, "u {x}: z {found} vs {zv}");
    }
}

/// The smallest root in [0, 1] by bisection of a monotone cubic (the test data's are).
fn first_root_test(c: [f64; 4], y: f64) -> Option<f64> {
    let g = |t: f64| ((c[3] * t + c[2]) * t + c[1]) * t + c[0] - y;
    if g(0.0).signum() == g(1.0).signum() {
        return None;
    }
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if g(mid).signum() == g(lo).signum() {
            lo = mid
        } else {
            hi = mid
        }
    }
    Some(lo)
}

/// Slices lacking their first samples: those samples exist from the first slice that has them
/// on (the rows of its run), the rest everywhere; the surface passes through every active
/// sample of every slice.
#[test]
fn an_interruption_starts_at_its_first_slice() {
    let u: Vec<f64> = (0..12).map(|i| i as f64 * 10.0).collect();
    let m = 14;
    let (y, z) = data(&u, m);
    let active: Vec<(usize, usize)> = (0..12).map(|i| if i < 5 { (6, m - 1) } else { (0, m - 1) }).collect();
    let s = Masked::new(&u, &y, &z, &active).unwrap();
    for (i, &x) in u.iter().enumerate() {
        for (j, sample) in s.samples_at(x).into_iter().enumerate() {
            match sample {
                Some((yy, zz)) => {
                    assert!(j >= active[i].0, "u {x}: sample {j} should be missing");
                    assert!((yy - y[i][j]).abs() < 1e-9 && (zz - z[i][j]).abs() < 1e-9, "u {x}, j {j}");
                }
                None => assert!(j < active[i].0, "u {x}: sample {j} missing"),
            }
        }
    }
    assert!(s.samples_at(45.0)[0].is_none() && s.samples_at(50.0)[0].is_some());
}

/// CONTACT's requirements on the mask: errors 171, 172.
#[test]
fn masks_contact_refuses_are_refused() {
    let u: Vec<f64> = (0..8).map(|i| i as f64).collect();
    let m = 10;
    let (y, z) = data(&u, m);
    let one_short: Vec<(usize, usize)> = (0..8).map(|i| if i < 3 { (1, m - 1) } else { (0, m - 1) }).collect();
    let e = Masked::new(&u, &y, &z, &one_short).unwrap_err();
    assert!(e.what.contains("slice 1") && e.allowed.contains("171"), "{e:?}");
    let three_slices: Vec<(usize, usize)> =
        (0..8).map(|i| if (2..5).contains(&i) { (0, m - 1) } else { (4, m - 1) }).collect();
    let e = Masked::new(&u, &y, &z, &three_slices).unwrap_err();
    assert!(e.what.contains("path of sample 1") && e.allowed.contains("172"), "{e:?}");
}
