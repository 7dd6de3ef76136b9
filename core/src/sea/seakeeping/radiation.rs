//! Two-dimensional radiation in deep water by the multipole method of Ursell (1949) as extended
//! to mapped sections by Tasai (1959) and Porter (1960): added mass and damping per unit length of
//! a section oscillating in sway, heave and roll (thesis ch. 2.5.1, the MIT5D method).
//!
//! Conventions. Section plane z = x + i y, x across (port positive), y up, fluid below y = 0;
//! time factor e^{i omega t}; nu = omega^2 / g. The potential of a mode with unit velocity
//! amplitude is psi = Q S(z) + sum_m c_m Re W_m(zeta), with complex Q and c_m:
//!
//! - S is the wave source at the origin (heave) or its x-derivative, the horizontal wave dipole
//!   (sway, roll): S = Re F - i pi Re e^{-i nu z} with F(z) = PV int_0^inf e^{-ikz}/(k - nu) dk
//!   = e^{-i nu z} (E1(-i nu z) - i pi) for x > 0, so that far away psi ~ -i pi Q e^{nu y}
//!   e^{-i nu |x|}: outgoing waves.
//! - W_m are multipoles that satisfy the free-surface condition of the mapped plane,
//!   Re(i dW/dzeta) = nu z'(zeta) Re W on the real zeta axis:
//!   W = zeta^-p + i nu M sum_j c_j zeta^-(q_j) / q_j, where z'(zeta) = M sum_j c_j zeta^-e_j and
//!   q_j = p + e_j - 1 (p = 2m for heave, 2m + 1 for sway and roll; for the Lewis form this is
//!   Tasai's zeta^-2m + i nu M (zeta^-(2m-1)/(2m-1) - a1 zeta^-(2m+1)/(2m+1) - 3 a3 ...)); the
//!   first term of each class is a regular combination that removes the source's near-field
//!   singularity (see `regular_odd` and `regular_even` in `solve`).
//!
//! The body condition d psi/dn = N_j is imposed in the least-squares sense on Gauss-Legendre nodes
//! of the half contour (weighted, so the residual's integral is minimised), which is how Ursell
//! solved it too. a_jk - i b_jk / omega = -rho int psi_k N_j dl over the whole contour.
//! The damping follows also from the far-field wave (energy flux): b = rho omega pi^2 |Q|^2 for the
//! source, rho omega pi^2 nu^2 |Q|^2 for the dipole; tests check the two routes agree.

use super::conformal::SectionMap;
use crate::numerics::complex::{cabs, cexp, exp_e1};
use crate::numerics::gauss_legendre;
use nalgebra::DMatrix;
use num_complex::Complex64 as C;
use std::f64::consts::PI;

/// Quadrature and collocation nodes on the half contour (x >= 0), from the waterline to the keel.
#[derive(Debug, Clone)]
pub struct Contour {
    /// Gauss-Legendre weights in the circle-plane angle theta in (-pi/2, 0).
    pub weight: Vec<f64>,
    pub zeta: Vec<C>,
    /// Section-plane points \[m\].
    pub z: Vec<C>,
    /// z'(zeta) zeta: its direction is the outward normal (into the fluid), its modulus |dz/dtheta|.
    pub dzt: Vec<C>,
    /// N_j |dz/dtheta| for j = sway (N2 = n_x), heave (N3 = n_y), roll (N4 = x n_y - y n_x) [m, m, m^2].
    pub nl: [Vec<f64>; 3],
}

/// Number of contour nodes (half section).
pub const NODES: usize = 48;

impl Contour {
    pub fn new(map: &SectionMap) -> Contour {
        let (th, weight) = gauss_legendre(NODES, -PI / 2.0, 0.0);
        let zeta: Vec<C> = th.iter().map(|&t| C::new(libm::cos(t), libm::sin(t))).collect();
        let z: Vec<C> = zeta.iter().map(|&s| map.z(s)).collect();
        let dzt: Vec<C> = zeta.iter().map(|&s| map.dz(s) * s).collect();
        let n2 = dzt.iter().map(|d| d.re).collect();
        let n3 = dzt.iter().map(|d| d.im).collect();
        let n4 = z.iter().zip(&dzt).map(|(z, d)| (z.conj() * d).im).collect();
        Contour { weight, zeta, z, dzt, nl: [n2, n3, n4] }
    }
}

/// Sectional coefficients of one section at one frequency (per unit length).
#[derive(Debug, Clone)]
pub struct Radiation2d {
    pub omega: f64,
    /// Added mass [kg/m] (a22, a33), [kg m] (a44), \[kg\] (a24).
    pub a22: f64,
    pub a33: f64,
    pub a44: f64,
    pub a24: f64,
    /// Damping [kg/(m s)] (b22, b33), [kg m/s] (b44), [kg/s] (b24).
    pub b22: f64,
    pub b33: f64,
    pub b44: f64,
    pub b24: f64,
    /// The same damping from the radiated wave amplitude (energy flux): [b22, b33, b44].
    pub b_far: [f64; 3],
    /// Potentials for unit velocity (sway, heave) or unit angular velocity (roll) on the contour
    /// nodes [m, m, m^2]; sway and roll are odd in x, heave even.
    pub psi: [Vec<C>; 3],
    /// Source (heave) and dipole (sway, roll) strengths Q.
    pub q: [C; 3],
    pub multipoles: usize,
}

/// Multipoles used at `nu` for `map`: more for higher circle-plane wave numbers nu M; at most 22,
/// so the least squares on the 48 nodes stays overdetermined two to one. With the regular first
/// terms few are needed (the convergence test shows the default converged to 1e-3).
pub fn default_multipoles(nu: f64, map: &SectionMap) -> usize {
    (6.0 + nu * map.scale).ceil().min(22.0) as usize
}

/// The 2-D radiation problem of `map` at frequency `omega` [rad/s], water density `rho`, gravity
/// `g`, with `n_mult` multipoles per symmetry class.
pub fn solve(map: &SectionMap, c: &Contour, omega: f64, rho: f64, g: f64, n_mult: usize) -> Radiation2d {
    let nu = omega * omega / g;
    let p = c.zeta.len();
    // Exponents e_j and coefficients c_j of z'(zeta) = M sum c_j zeta^-e_j.
    let mut zc: Vec<(usize, f64)> = vec![(0, 1.0)];
    for (i, &a) in map.coeffs.iter().enumerate() {
        let k = 2 * i + 1;
        zc.push((k + 1, -(k as f64) * a));
    }
    let max_pow = 2 * n_mult + 2 + zc.last().map(|e| e.0).unwrap_or(0) + 1;
    // Inverse powers zeta^-n at every node.
    let pows: Vec<Vec<C>> = c
        .zeta
        .iter()
        .map(|&s| {
            let inv = C::new(1.0, 0.0) / s;
            let mut v = Vec::with_capacity(max_pow + 1);
            let mut t = C::new(1.0, 0.0);
            for _ in 0..=max_pow {
                v.push(t);
                t *= inv;
            }
            v
        })
        .collect();
    let num = nu * map.scale;
    // Multipole value Re W and normal derivative Re(zeta W') at node i for order p.
    let multipole = |i: usize, pw: usize| -> (f64, f64) {
        let v = &pows[i];
        let mut w = v[pw];
        let mut dw = v[pw] * -(pw as f64);
        for &(e, cj) in &zc {
            let q = pw + e - 1;
            w += C::new(0.0, num * cj / q as f64) * v[q];
            dw -= C::new(0.0, num * cj) * v[q];
        }
        (w.re, dw.re)
    };
    // Sources: value and normal derivative (times |dz/dtheta|), both complex.
    let mut src_heave = Vec::with_capacity(p);
    let mut src_sway = Vec::with_capacity(p);
    for i in 0..p {
        let z = c.z[i];
        let u = C::new(0.0, -nu) * z;
        let eu = cexp(u);
        let f = exp_e1(u) - C::new(0.0, PI) * eu;
        let f1 = C::new(0.0, -nu) * f - C::new(1.0, 0.0) / z;
        let f2 = C::new(0.0, -nu) * f1 + C::new(1.0, 0.0) / (z * z);
        let d = c.dzt[i];
        let ipi = C::new(0.0, -PI);
        let val_h = C::new(f.re, 0.0) + ipi * eu.re;
        let dn_h = C::new((f1 * d).re, 0.0) + ipi * (C::new(0.0, -nu) * eu * d).re;
        let val_s = C::new(f1.re, 0.0) + ipi * (C::new(0.0, -nu) * eu).re;
        let dn_s = C::new((f2 * d).re, 0.0) + ipi * (eu * d * -(nu * nu)).re;
        src_heave.push((val_h, dn_h));
        src_sway.push((val_s, dn_s));
    }
    // Regular terms that take out the near-singularity of the source (log z) and dipole (1/z) at
    // the physical origin: for deep narrow sections the zeros of z(zeta) lie close to the unit
    // circle at the waterline, and the zeta^-p series alone then converges very slowly.
    // Odd class: zeta^-1 - M/z + i nu M (sum_{e_j>0} c_j zeta^-e_j / e_j + log(z / (M zeta))),
    // which satisfies the free-surface condition in closed form.
    // Even class: L = log(z / (M zeta)) = sum_n l_n zeta^-2n, as the same combination of the
    // even multipoles, sum_n l_n W_2n (the series converges on the circle because every zero of
    // z(zeta) lies inside it).
    let circle = map.coeffs.iter().all(|a| a.abs() < 1e-9);
    let mut ell = Vec::new();
    if !circle {
        // log f(t), f = 1 + sum_i a_(2i+1) t^(i+1), t = zeta^-2: n l_n = n f_n - sum_j j l_j f_(n-j).
        let f = |j: usize| if j == 0 { 1.0 } else { map.coeffs.get(j - 1).copied().unwrap_or(0.0) };
        for n in 1..=600usize {
            let mut v = n as f64 * f(n);
            for j in 1..n {
                v -= j as f64 * ell[j - 1] * f(n - j);
            }
            ell.push(v / n as f64);
            if n > 4 && ell[n - 5..].iter().all(|l: &f64| l.abs() < 1e-14) {
                break;
            }
        }
    }
    let regular_odd: Vec<(f64, f64)> = (0..p)
        .map(|i| {
            let (zeta, z, v) = (c.zeta[i], c.z[i], &pows[i]);
            let zp = map.dz(zeta);
            let mut w = v[1] - map.scale / z;
            let mut dw = -v[1] + zeta * zp * map.scale / (z * z);
            let mut sum = crate::numerics::complex::cln(z / (zeta * map.scale));
            let mut dsum = zeta * zp / z - 1.0;
            for &(e, cj) in zc.iter().skip(1) {
                sum += v[e] * (cj / e as f64);
                dsum -= v[e] * cj;
            }
            w += C::new(0.0, num) * sum;
            dw += C::new(0.0, num) * dsum;
            (w.re, dw.re)
        })
        .collect();
    let regular_even: Vec<(f64, f64)> = (0..p)
        .map(|i| {
            let inv2 = pows[i][2];
            let inv = pows[i][1];
            // zeta^-(2n) and the companion powers zeta^-(2n + e_j - 1), built incrementally.
            let (mut w, mut dw) = (C::new(0.0, 0.0), C::new(0.0, 0.0));
            let mut t2n = inv2;
            for (k, &l) in ell.iter().enumerate() {
                let pw = 2 * (k + 1);
                let mut wm = t2n;
                let mut dwm = t2n * -(pw as f64);
                let mut tq = t2n * c.zeta[i]; // zeta^-(2n-1), e = 0
                let mut last_e = 0;
                for &(e, cj) in &zc {
                    for _ in last_e..e {
                        tq *= inv;
                    }
                    last_e = e;
                    let q = pw + e - 1;
                    wm += C::new(0.0, num * cj / q as f64) * tq;
                    dwm -= C::new(0.0, num * cj) * tq;
                }
                w += wm * l;
                dw += dwm * l;
                t2n *= inv2;
            }
            (w.re, dw.re)
        })
        .collect();
    // Least squares for one symmetry class: unknowns [Re Q, Im Q, Re c_1.., Im c_1..]; column j
    // of the multipoles comes from `basis(i, j)` = (value, normal derivative).
    let solve_class =
        |src: &[(C, C)], basis: &dyn Fn(usize, usize) -> (f64, f64), rhs: &[&Vec<f64>]| -> Vec<(C, Vec<C>)> {
            let nun = 2 * n_mult + 2;
            let mut a = DMatrix::<f64>::zeros(2 * p, nun);
            let mut mvals = vec![vec![0.0; n_mult]; p];
            for i in 0..p {
                let sw = c.weight[i].sqrt();
                let (_, dn) = src[i];
                a[(2 * i, 0)] = sw * dn.re;
                a[(2 * i, 1)] = -sw * dn.im;
                a[(2 * i + 1, 0)] = sw * dn.im;
                a[(2 * i + 1, 1)] = sw * dn.re;
                for m in 0..n_mult {
                    let (val, dn) = basis(i, m);
                    mvals[i][m] = val;
                    a[(2 * i, 2 + m)] = sw * dn;
                    a[(2 * i + 1, 2 + n_mult + m)] = sw * dn;
                }
            }
            // Column scaling keeps the dipole column (O(nu)) and the multipoles comparable.
            let scale: Vec<f64> = (0..nun).map(|j| 1.0 / a.column(j).norm().max(1e-300)).collect();
            for (j, &s) in scale.iter().enumerate() {
                a.column_mut(j).scale_mut(s);
            }
            let qr = a.qr();
            let (q, r) = (qr.q(), qr.r());
            rhs.iter()
                .map(|nl| {
                    let mut b = nalgebra::DVector::<f64>::zeros(2 * p);
                    for i in 0..p {
                        b[2 * i] = c.weight[i].sqrt() * nl[i];
                    }
                    let y = q.transpose() * b;
                    let x = r.solve_upper_triangular(&y).unwrap_or_else(|| nalgebra::DVector::zeros(nun));
                    let x: Vec<f64> = x.iter().zip(&scale).map(|(x, s)| x * s).collect();
                    let qs = C::new(x[0], x[1]);
                    let cs: Vec<C> = (0..n_mult).map(|m| C::new(x[2 + m], x[2 + n_mult + m])).collect();
                    let psi: Vec<C> = (0..p)
                        .map(|i| qs * src[i].0 + cs.iter().zip(&mvals[i]).map(|(c, v)| c * v).sum::<C>())
                        .collect();
                    (qs, psi)
                })
                .collect()
        };
    // With the regular term first, the multipoles start one order later (p = 2m, 2m + 1 from
    // m = 1 on the circle, where the regular terms vanish).
    // `parity` 0: even class (orders 2, 4, ...); 1: odd class (3, 5, ...).
    let class = |regular: &[(f64, f64)], parity: usize, i: usize, m: usize| {
        if circle {
            multipole(i, 2 * m + 2 + parity)
        } else if m == 0 {
            regular[i]
        } else {
            multipole(i, 2 * m + parity)
        }
    };
    let even = |i: usize, m: usize| class(&regular_even, 0, i, m);
    let odd_b = |i: usize, m: usize| class(&regular_odd, 1, i, m);
    let heave = solve_class(&src_heave, &even, &[&c.nl[1]]);
    let odd = solve_class(&src_sway, &odd_b, &[&c.nl[0], &c.nl[2]]);
    let (q3, psi3) = heave.into_iter().next().unwrap_or_default();
    let mut odd = odd.into_iter();
    let (q2, psi2) = odd.next().unwrap_or_default();
    let (q4, psi4) = odd.next().unwrap_or_default();
    // -rho * 2 * int_half psi_k N_j dl = a_jk - i b_jk / omega
    let integ =
        |psi: &[C], j: usize| -> C { (0..p).map(|i| psi[i] * (c.weight[i] * c.nl[j][i])).sum::<C>() * (-2.0 * rho) };
    let (i22, i33, i44, i24) = (integ(&psi2, 0), integ(&psi3, 1), integ(&psi4, 2), integ(&psi4, 0));
    let sq = |q: C| q.re * q.re + q.im * q.im;
    Radiation2d {
        omega,
        a22: i22.re,
        a33: i33.re,
        a44: i44.re,
        a24: i24.re,
        b22: -omega * i22.im,
        b33: -omega * i33.im,
        b44: -omega * i44.im,
        b24: -omega * i24.im,
        b_far: [
            rho * omega * PI * PI * nu * nu * sq(q2),
            rho * omega * PI * PI * sq(q3),
            rho * omega * PI * PI * nu * nu * sq(q4),
        ],
        psi: [psi2, psi3, psi4],
        q: [q2, q3, q4],
        multipoles: n_mult,
    }
}

/// Convenience: the coefficients of `map` at `omega` with the default number of multipoles.
pub fn coefficients(map: &SectionMap, omega: f64, rho: f64, g: f64) -> Radiation2d {
    let c = Contour::new(map);
    solve(map, &c, omega, rho, g, default_multipoles(omega * omega / g, map))
}

/// |q| helper for callers that report far-field wave amplitudes.
pub fn modulus(q: C) -> f64 {
    cabs(q)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sea::seakeeping::conformal::{section_map, Form};

    const RHO: f64 = 1025.0;
    const G: f64 = 9.81;
    /// rho pi a^2 / 2 for the unit semicircle.
    const NORM: f64 = RHO * PI / 2.0;

    fn semicircle(ka: f64) -> Radiation2d {
        let m = section_map(1.0, 1.0, PI / 4.0).unwrap();
        coefficients(&m, (ka * G).sqrt(), RHO, G)
    }

    /// Near field (pressure integral) and far field (radiated wave energy flux) give the same
    /// damping, within 1 % (they agree to about 1e-4), for the semicircle, Lewis forms and a bulb.
    #[test]
    fn damping_from_near_and_far_field_agree() {
        let maps = [
            section_map(1.0, 1.0, PI / 4.0).unwrap(),
            section_map(9.5, 6.15, 0.85).unwrap(),
            section_map(9.0, 6.15, 0.62).unwrap(),
            // A sonar-dome section of the 5415 (station 19.5) in the bulb form.
            crate::sea::seakeeping::conformal::bulb(0.725, 9.16, 1.834).unwrap(),
        ];
        assert_eq!(maps[3].form, Form::Bulb);
        for m in &maps {
            let c = Contour::new(m);
            for &w in &[0.2, 0.5, 0.8, 1.2, 2.0] {
                let r = solve(m, &c, w, RHO, G, default_multipoles(w * w / G, m));
                for (near, far, a, name) in [
                    (r.b22, r.b_far[0], r.a22, "b22"),
                    (r.b33, r.b_far[1], r.a33, "b33"),
                    (r.b44, r.b_far[2], r.a44, "b44"),
                ] {
                    if name == "b44" && m.coeffs.iter().all(|a| a.abs() < 1e-12) {
                        continue; // the circle has no roll damping (checked below)
                    }
                    // Where the damping is below 1e-3 of omega a (a deep narrow section swaying
                    // slowly) the near-field value is at the level of the least-squares residual: the check
                    // is that both are negligible, |near - far| < 1e-3 omega a.
                    if far < 1e-3 * w * a {
                        // Measured 8.0e-6 omega a.
                        assert!((near - far).abs() < 1e-4 * w * a, "{name} at {w}: {near} vs {far}, a {a}");
                        continue;
                    }
                    assert!((near - far).abs() < 0.01 * far, "{name} at omega {w}, {m:?}: near {near} far {far}");
                }
            }
        }
    }

    /// Limits of the semicircle: heave added mass to rho pi a^2 / 2 at high frequency and without
    /// bound at low frequency; sway added mass to rho pi a^2 / 2 at low frequency; damping to zero
    /// at both ends; low-frequency heave damping to 4 rho omega a^2 (the body then acts as a source
    /// of the flux it displaces, beam times velocity); no roll moment on a circle about its centre.
    #[test]
    fn semicircle_limits() {
        let hi = semicircle(40.0);
        assert!((hi.a33 / NORM - 1.0).abs() < 0.02, "a33(inf) {}", hi.a33 / NORM);
        // Measured at the ends of the range: a33(inf) 1.09 % off, b33(inf) 4.2e-6, a22(0) 1.3e-4 off,
        // b22(0) 6.3e-8, b33(0) 1.3e-3 off.
        assert!(hi.b33 / (NORM * (40.0 * G).sqrt()) < 2e-5);
        let lo = semicircle(1e-4);
        assert!((lo.a22 / NORM - 1.0).abs() < 1e-3, "a22(0) {}", lo.a22 / NORM);
        assert!(lo.b22 / (NORM * (1e-4 * G).sqrt()) < 1e-6);
        let w = (1e-4 * G).sqrt();
        assert!((lo.b33 / (4.0 * RHO * w) - 1.0).abs() < 5e-3, "b33(0) {}", lo.b33 / (4.0 * RHO * w));
        let a: Vec<f64> = [1e-1, 1e-2, 1e-3, 1e-4].iter().map(|&k| semicircle(k).a33 / NORM).collect();
        assert!(a.windows(2).all(|w| w[1] > w[0] + 0.3), "a33 grows as omega -> 0: {a:?}");
        for ka in [0.1, 1.0, 3.0] {
            let r = semicircle(ka);
            assert!(r.a44.abs() < 1e-9 * NORM && r.b44.abs() < 1e-9 * NORM && r.a24.abs() < 1e-9 * NORM);
        }
    }

    /// The classical heave curve of the semicircle (Ursell 1949, Porter 1960, Vugts 1968
    /// experiments): the added mass coefficient has its minimum of about 0.6 near Ka = 0.8-1
    /// (tolerance 0.05 on the value, read off the published curves), and the sway coefficient
    /// peaks above 1 near Ka = 0.2-0.3 before falling.
    #[test]
    fn semicircle_heave_minimum_where_published() {
        let ks: Vec<f64> = (1..=40).map(|i| 0.05 * i as f64).collect();
        let a: Vec<f64> = ks.iter().map(|&k| semicircle(k).a33 / NORM).collect();
        let (imin, amin) = a.iter().enumerate().fold((0, f64::INFINITY), |b, (i, &v)| if v < b.1 { (i, v) } else { b });
        println!("heave added mass minimum {amin:.4} at Ka {:.2}", ks[imin]);
        assert!((amin - 0.6).abs() < 0.05 && (0.7..=1.1).contains(&ks[imin]));
        let s: Vec<f64> = ks.iter().map(|&k| semicircle(k).a22 / NORM).collect();
        let (imax, smax) = s.iter().enumerate().fold((0, 0.0), |b, (i, &v)| if v > b.1 { (i, v) } else { b });
        println!("sway added mass maximum {smax:.4} at Ka {:.2}", ks[imax]);
        assert!(smax > 1.1 && (0.1..=0.4).contains(&ks[imax]));
    }

    /// Convergence in the number of multipoles: going from the default to 8 more changes nothing
    /// beyond 1e-3 (relative to the larger of added mass and damping) for the semicircle, a full
    /// and a fine Lewis form, up to nu M = 8.
    #[test]
    fn multipole_series_has_converged() {
        for m in [
            section_map(1.0, 1.0, PI / 4.0).unwrap(),
            section_map(9.5, 6.15, 0.9).unwrap(),
            section_map(6.0, 6.15, 0.55).unwrap(),
        ] {
            let c = Contour::new(&m);
            for &num in &[0.1, 1.0, 3.0, 8.0] {
                let w = (num / m.scale * G).sqrt();
                let n0 = default_multipoles(num / m.scale, &m);
                let r0 = solve(&m, &c, w, RHO, G, n0);
                let r1 = solve(&m, &c, w, RHO, G, n0 + 8);
                for (x0, x1, y0) in
                    [(r0.a33, r1.a33, r0.b33 / w), (r0.a22, r1.a22, r0.b22 / w), (r0.b33 / w, r1.b33 / w, r0.a33)]
                {
                    let sc = x0.abs().max(y0.abs());
                    assert!((x0 - x1).abs() < 1e-3 * sc, "nu M {num}: {x0} vs {x1} ({m:?})");
                }
                let print = |n: usize| {
                    let r = solve(&m, &c, w, RHO, G, n);
                    format!("{n}: a33 {:.6e} b33 {:.6e}", r.a33, r.b33)
                };
                if num == 3.0 {
                    println!(
                        "convergence nu M = 3, {:?}: {} | {} | {} | {}",
                        m.form,
                        print(2),
                        print(4),
                        print(8),
                        print(n0)
                    );
                }
            }
        }
    }
}
