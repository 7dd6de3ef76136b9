//! The ship's motions in regular waves by Salvesen-Tuck-Faltinsen (1970) strip theory (thesis ch.
//! 2.5.2, eqs. 2.37-2.43, Appendix A): the sectional Froude-Krylov and diffraction forces, the
//! coupled sway-roll-yaw and heave-pitch equations with the equivalent linear roll damping
//! iteration (eqs. 2.44-2.45), and the natural periods. The ship, its strips and their sectional
//! coefficients are `strip`'s; the axes and conventions are stated there.

use super::radiation::Contour;
use super::reflection::{reflection_force, ShortWaveForce};
use super::roll_damping::components;
use super::strip::{RadiationTable, Sect, Ship};
use crate::as_printed::AsPrintedParams;
use crate::numerics::complex::cexp;
use num_complex::Complex64 as C;

/// The ship's linear response to a regular wave of unit amplitude.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Response {
    pub omega0: f64,
    pub omega_e: f64,
    pub k: f64,
    /// Complex RAOs (amplitude per metre of wave amplitude, phase relative to the crest at the
    /// origin): sway, heave [m/m]; roll, pitch, yaw [rad/m].
    pub sway: C,
    pub heave: C,
    pub roll: C,
    pub pitch: C,
    pub yaw: C,
    /// Mean second-order force along the waves' direction of travel per wave amplitude squared
    /// (F_add of eq. 2.47) [N/m^2]; its components in ship axes (eq. 2.46).
    pub f_add: f64,
    /// The same for the sway component (sin(beta) f_add_sway): equal to `f_add` with eq. 2.48's
    /// F7, with the waterline's reflection its short-wave part is F7 at zero speed
    /// (`ShortWaveForce`).
    pub f_add_sway: f64,
    pub added_resistance: f64,
    pub drift_force: f64,
    /// Mean second-order yaw moment about the centre of gravity per wave amplitude squared,
    /// positive bow to port (M_add of eqs. 2.19 and 2.24) [N m/m^2]: the moment of the sectional
    /// drift force, see `response_as`.
    pub drift_moment: f64,
    /// The Gerritsma-Beukelman added resistance (radiated-energy method) [N/m^2], an independent
    /// estimate kept for comparison.
    pub added_resistance_gb: f64,
    /// Equivalent linear viscous roll damping used [N m s/rad].
    pub b44_viscous: f64,
}

/// Sectional exciting forces per unit wave amplitude and density, without the longitudinal phase
/// e^{-i k x cos beta}: Froude-Krylov f_j = -g int e^{kz - i k y sin beta} N_j dl and diffraction
/// h_j = -i omega_e omega0 int psi_j e^{kz - i k y sin beta} (i N3 + sin beta N2) dl (STF's
/// approximation: the incident wave's normal velocity without its x component, returned through
/// the radiation potential by Green's theorem), for sway, heave, roll; and the diffraction with
/// the conjugate incident wave (for eq. 2.47).
pub fn sectional_forces(
    c: &Contour,
    psi: &[Vec<C>; 3],
    k: f64,
    sb: f64,
    we: f64,
    omega0: f64,
    g: f64,
) -> ([C; 3], [C; 3], [C; 3]) {
    let (mut fs, mut ev, mut evc, mut od) = ([0.0f64; 3], C::new(0.0, 0.0), C::new(0.0, 0.0), [C::new(0.0, 0.0); 2]);
    #[allow(clippy::needless_range_loop)] // six parallel arrays indexed by node
    for q in 0..c.weight.len() {
        let (x, y) = (c.z[q].re, c.z[q].im);
        let w2q = 2.0 * c.weight[q] * libm::exp(k * y);
        let (cs, sn) = (libm::cos(k * x * sb), libm::sin(k * x * sb));
        let (n2, n3, n4) = (c.nl[0][q], c.nl[1][q], c.nl[2][q]);
        // Even and odd parts in the lateral coordinate: the contour integral over both sides is
        // twice the half-contour integral of the part with the potential's parity.
        fs[0] += w2q * n2 * sn;
        fs[1] += w2q * n3 * cs;
        fs[2] += w2q * n4 * sn;
        let even = C::new(0.0, n3 * cs - sb * n2 * sn);
        let odd = n3 * sn + sb * n2 * cs;
        ev += psi[1][q] * even * w2q;
        evc += psi[1][q] * even.conj() * w2q;
        od[0] += psi[0][q] * (odd * w2q);
        od[1] += psi[2][q] * (odd * w2q);
    }
    let pre = C::new(0.0, -we * omega0);
    let f = [C::new(0.0, g * fs[0]), C::new(-g * fs[1], 0.0), C::new(0.0, g * fs[2])];
    let h = [pre * od[0], pre * ev, pre * od[1]];
    let hh = [pre * od[0], pre * evc, pre * od[1]];
    (f, h, hh)
}

/// Solves a small complex linear system by Gaussian elimination with partial pivoting
/// (|re| + |im| as the pivot size, so no platform hypot is involved).
fn solve_small<const N: usize>(mut a: [[C; N]; N], mut b: [C; N]) -> [C; N] {
    let size = |c: C| c.re.abs() + c.im.abs();
    for col in 0..N {
        let piv = (col..N).max_by(|&i, &j| size(a[i][col]).total_cmp(&size(a[j][col]))).unwrap_or(col);
        a.swap(col, piv);
        b.swap(col, piv);
        let d = a[col][col];
        if size(d) == 0.0 {
            return [C::new(f64::NAN, f64::NAN); N];
        }
        for r in col + 1..N {
            let f = a[r][col] / d;
            let pivot_row = a[col];
            for (x, v) in a[r].iter_mut().zip(pivot_row).skip(col) {
                *x -= f * v;
            }
            let v = b[col];
            b[r] -= f * v;
        }
    }
    let mut x = [C::new(0.0, 0.0); N];
    for r in (0..N).rev() {
        let mut s = b[r];
        for c in r + 1..N {
            s -= a[r][c] * x[c];
        }
        x[r] = s / a[r][r];
    }
    x
}

/// The response to a unit-amplitude regular wave of frequency `omega0` [rad/s] at ship speed `u`
/// [m/s] and heading `beta` \[rad\] (180 deg head seas), with the nonlinear roll damping linearised
/// at the roll amplitude reached in waves of amplitude `roll_wave_amplitude` \[m\] (eq. 2.45,
/// iterated to 0.1 %).
pub fn response(
    ship: &Ship,
    table: &RadiationTable,
    omega0: f64,
    u: f64,
    beta: f64,
    roll_wave_amplitude: f64,
) -> Response {
    response_as(ship, table, omega0, u, beta, roll_wave_amplitude, &AsPrintedParams::default())
}

/// `response` with the thesis' equations as printed where `printed` says so: Appendix A's eqs. 5
/// and 17 (`appendix_a_typos`) and eq. 2.47's conjugate (`eq_2_47_conjugate`).
///
/// The yaw drift moment M_add (named in eqs. 2.19 and 2.24, no formula in the thesis) is the
/// moment about the centre of gravity of the sectional drift force,
///
///   M_add = sin(beta) [ sum_strips w_i xi_i (s_i + f7_i) + xi_A s_A ],
///
/// where s_i is strip i's share of eq. 2.47's sum and f7_i its share of eq. 2.48, so that
/// sum_i w_i (s_i + f7_i) + s_A = F_add to round-off (tested):
///
///   s_i = Re{ (i k / 2) rho [ (H2 + xi H6) (conj f2 + cj h2) + (H3 - xi H5) (conj f3 + cj h3)
///                             + H4 (conj f4 + cj h4) + cj(U/(i omega_e)) (H6 cj h2 - H5 cj h3) ] },
///   s_A = Re{ (i k / 2) rho cj(U/(i omega_e)) [ (H2 + xi_A H6) cj h2 + (H3 - xi_A H5) cj h3
///                                               + H4 cj h4 ]_A }   (the transom terms),
///   f7_i = (1/2) k (omega0^2 / omega_e) e^{-2 k d_s} (b33 + sin^2 beta b22),
///
/// with f_j the sectional Froude-Krylov force (incident wave's phase at the strip), h_j the
/// sectional diffraction force of the conjugate incident wave, and cj the complex conjugate
/// (none with `printed.eq_2_47_conjugate`, as for F_add). The weights (H2 + xi H6, H3 - xi H5, H4)
/// are the strip's own displacement: Salvesen's sum over modes, sum_j H_j conj(F_j), regrouped
/// strip by strip.
///
/// Why the lever is xi sin(beta): Salvesen (1974, "Second-order steady-state forces and moments on
/// surface ships in oblique regular waves", Int. Symp. Dynamics of Marine Vehicles and Structures
/// in Waves, London) obtains the mean force from the change of the exciting forces when the ship
/// is displaced against the incident wave, e^{-i k (x cos beta + y sin beta)}: a shift s along the
/// waves' direction multiplies every strip's exciting force by e^{-i k s}, which gives F_add (eq.
/// 2.47) and its components cos(beta) F_add, sin(beta) F_add (eq. 2.46). A small yaw delta (bow to
/// port) moves the strip at xi by delta xi to port, changing its phase by e^{-i k xi sin(beta)
/// delta}: the strip's share of the moment is its share of F_add times xi sin(beta), i.e.
/// xi times the sectional drift force. This is the slender-body (strip) form of Salvesen's yaw
/// moment; it leaves out (plainly, as an approximation): the moment of the longitudinal force
/// about the hull's half-breadth (the -y cos(beta) part of the rotation, of relative order B/L),
/// the change of the waves' heading seen by each section under the yaw, and the products of the
/// first-order rotations with first-order moments (roll x pitch moment, Pinkster's rotation terms).
/// F7 (eq. 2.48) is already a sectional integral and is given the same lever. The moment goes
/// with the sway force: with the waterline's reflection for the surge force (`Ship::short_wave`)
/// f7_i is F7's density at zero speed, as in `f_add_sway`.
pub fn response_as(
    ship: &Ship,
    table: &RadiationTable,
    omega0: f64,
    u: f64,
    beta: f64,
    roll_wave_amplitude: f64,
    printed: &AsPrintedParams,
) -> Response {
    response_parts(ship, table, omega0, u, beta, roll_wave_amplitude, printed).0
}

/// `response_as` and, second, the sectional sum of eq. 2.47 with a unit lever
/// (sum_i w_i (s_i + f7_i) + s_A, which is F_add): the check of the drift moment's density.
pub(super) fn response_parts(
    ship: &Ship,
    table: &RadiationTable,
    omega0: f64,
    u: f64,
    beta: f64,
    roll_wave_amplitude: f64,
    printed: &AsPrintedParams,
) -> (Response, f64, HeavePitchSystem) {
    let (rho, g) = (ship.rho, ship.g);
    let k = omega0 * omega0 / g;
    let (sb, cb) = (libm::sin(beta), libm::cos(beta));
    // Encounter frequency; for overtaken following seas its magnitude (eq. 2.52), and never below
    // the grid's lowest frequency.
    let we = (omega0 - k * u * cb).abs().max(table.omegas[0]);
    let iw = C::new(0.0, we);
    let uw = u / we;
    let n = ship.strips.len();
    let a = ship.aft;
    let xa = ship.strips[a].xi;
    // Sectional values and integrals.
    let secs: Vec<Sect> = (0..n).map(|i| table.at(i, we)).collect();
    let int = |f: &dyn Fn(usize) -> f64| -> f64 { (0..n).map(|i| ship.strips[i].weight * f(i)).sum() };
    let intc = |f: &dyn Fn(usize) -> C| -> C { (0..n).map(|i| f(i) * ship.strips[i].weight).sum() };
    let xi = |i: usize| ship.strips[i].xi;
    let (a33_0, b33_0) = (int(&|i| secs[i].a33), int(&|i| secs[i].b33));
    let (a22_0, b22_0) = (int(&|i| secs[i].a22), int(&|i| secs[i].b22));
    let (a24_0, b24_0) = (int(&|i| secs[i].a24), int(&|i| secs[i].b24));
    // The aft end's sectional values and U / (i omega_e) for its exciting forces; both zero
    // without the aft-end terms (`Ship::aft_end_terms`), which removes every superscript-A term.
    let no_end = Sect {
        a22: 0.0,
        a33: 0.0,
        a44: 0.0,
        a24: 0.0,
        b22: 0.0,
        b33: 0.0,
        b44: 0.0,
        b24: 0.0,
        psi: [Vec::new(), Vec::new(), Vec::new()],
    };
    let sa = if ship.aft_end_terms { &secs[a] } else { &no_end };
    let w2 = we * we;
    // Heave-pitch (Appendix A eqs. 4, 5, 8, 9, 16, 17, 20, 21 and 31, 32, 34).
    let a33 = a33_0 - u / w2 * sa.b33;
    let b33 = b33_0 + u * sa.a33;
    let a35 = -int(&|i| xi(i) * secs[i].a33) - u / w2 * b33_0 + u / w2 * xa * sa.b33 - uw * uw * sa.a33;
    let b35 = -int(&|i| xi(i) * secs[i].b33) + u * a33_0 - u * xa * sa.a33 - uw * uw * sa.b33;
    // Appendix A as printed: eq. 5 with -(U^2/omega^2) B33^0, eq. 17 with +U A53^0 (A53^0 =
    // -int xi a33, the zero-speed A53 of eq. 8).
    let (a35, b35) = if printed.appendix_a_typos {
        (
            -int(&|i| xi(i) * secs[i].a33) - u * u / w2 * b33_0 + u / w2 * xa * sa.b33 - uw * uw * sa.a33,
            -int(&|i| xi(i) * secs[i].b33) + u * (-int(&|i| xi(i) * secs[i].a33)) - u * xa * sa.a33 - uw * uw * sa.b33,
        )
    } else {
        (a35, b35)
    };
    let a53 = -int(&|i| xi(i) * secs[i].a33) + u / w2 * b33_0 + u / w2 * xa * sa.b33;
    let b53 = -int(&|i| xi(i) * secs[i].b33) - u * a33_0 - u * xa * sa.a33;
    let a55 =
        int(&|i| xi(i) * xi(i) * secs[i].a33) + uw * uw * a33_0 - u / w2 * xa * xa * sa.b33 + uw * uw * xa * sa.a33;
    let b55 = int(&|i| xi(i) * xi(i) * secs[i].b33) + uw * uw * b33_0 + u * xa * xa * sa.a33 + uw * uw * xa * sa.b33;
    let c33 = rho * g * int(&|i| ship.strips[i].beam);
    let c35 = -rho * g * int(&|i| xi(i) * ship.strips[i].beam);
    // C55 = rho g V GM_L: the waterplane's moment plus the small rho g V (z_B - z_G).
    let c55 = rho * g * (int(&|i| xi(i) * xi(i) * ship.strips[i].beam) + ship.volume * (ship.zb - ship.zg));
    // Sway-roll-yaw (eqs. 1-3, 6, 7, 10-15, 18, 19, 22-24, 33).
    let a22 = a22_0 - u / w2 * sa.b22;
    let b22 = b22_0 + u * sa.a22;
    let a24 = a24_0 - u / w2 * sa.b24;
    let b24 = b24_0 + u * sa.a24;
    let a26 = int(&|i| xi(i) * secs[i].a22) + u / w2 * b22_0 - u / w2 * xa * sa.b22 + uw * uw * sa.a22;
    let b26 = int(&|i| xi(i) * secs[i].b22) - u * a22_0 + u * xa * sa.a22 + uw * uw * sa.b22;
    let a44 = int(&|i| secs[i].a44) - u / w2 * sa.b44;
    let b44_pot = int(&|i| secs[i].b44) + u * sa.a44;
    let a46 = int(&|i| xi(i) * secs[i].a24) + u / w2 * b24_0 - u / w2 * xa * sa.b24 + uw * uw * sa.a24;
    let b46 = int(&|i| xi(i) * secs[i].b24) - u * a24_0 + u * xa * sa.a24 + uw * uw * sa.b24;
    let a62 = int(&|i| xi(i) * secs[i].a22) - u / w2 * b22_0 - u / w2 * xa * sa.b22;
    let b62 = int(&|i| xi(i) * secs[i].b22) + u * a22_0 + u * xa * sa.a22;
    let a64 = int(&|i| xi(i) * secs[i].a24) - u / w2 * b24_0 - u / w2 * xa * sa.b24;
    let b64 = int(&|i| xi(i) * secs[i].b24) + u * a24_0 + u * xa * sa.a24;
    let a66 =
        int(&|i| xi(i) * xi(i) * secs[i].a22) + uw * uw * a22_0 - u / w2 * xa * xa * sa.b22 + uw * uw * xa * sa.a22;
    let b66 = int(&|i| xi(i) * xi(i) * secs[i].b22) + uw * uw * b22_0 + u * xa * xa * sa.a22 + uw * uw * xa * sa.b22;
    let c44 = rho * g * ship.volume * ship.gm_t;
    // Exciting forces: Froude-Krylov f_j and diffraction h_j per strip (module doc), plus the
    // diffraction with the conjugate incident wave for eq. 2.47.
    let mut f = vec![[C::new(0.0, 0.0); 3]; n]; // sway, heave, roll
    let mut h = vec![[C::new(0.0, 0.0); 3]; n];
    let mut hh = vec![[C::new(0.0, 0.0); 3]; n];
    for i in 0..n {
        let st = &ship.strips[i];
        let ph = cexp(C::new(0.0, -k * st.xi * cb));
        let (fs, hs, hhs) = sectional_forces(&st.contour, &secs[i].psi, k, sb, we, omega0, g);
        f[i] = fs.map(|v| v * ph);
        h[i] = hs.map(|v| v * ph);
        hh[i] = hhs.map(|v| v * ph.conj());
    }
    let ui = C::new(u, 0.0) / iw;
    let ue = if ship.aft_end_terms { ui } else { C::new(0.0, 0.0) };
    // Forces per unit wave amplitude, [FK, diffraction] for sway, heave, roll, pitch, yaw.
    let forces = |h: &Vec<[C; 3]>| -> [C; 5] {
        let d = |j: usize| intc(&|i| h[i][j]) * rho + ue * h[a][j] * rho;
        [
            d(0),
            d(1),
            d(2),
            -(intc(&|i| h[i][1] * xi(i) + ui * h[i][1]) + ue * h[a][1] * xa) * rho,
            (intc(&|i| h[i][0] * xi(i) + ui * h[i][0]) + ue * h[a][0] * xa) * rho,
        ]
    };
    let fk = [
        intc(&|i| f[i][0]) * rho,
        intc(&|i| f[i][1]) * rho,
        intc(&|i| f[i][2]) * rho,
        -intc(&|i| f[i][1] * xi(i)) * rho,
        intc(&|i| f[i][0] * xi(i)) * rho,
    ];
    let fd = forces(&h);
    let fdh = forces(&hh);
    let ex: [C; 5] = std::array::from_fn(|j| fk[j] + fd[j]);
    // Heave and pitch.
    let m = ship.mass;
    let mp = ship.mass_props;
    let i5 = m * (mp.kyy_m * mp.kyy_m + ship.zg * ship.zg);
    let z = |mass: f64, damp: f64, stiff: f64| C::new(stiff - w2 * mass, we * damp);
    let hp = solve_small(
        [[z(m + a33, b33, c33), z(a35, b35, c35)], [z(a53, b53, c35), z(i5 + a55, b55, c55)]],
        [ex[1], ex[3]],
    );
    // Sway, roll, yaw with the roll damping iteration.
    let i4 = m * (mp.kxx_m * mp.kxx_m + ship.zg * ship.zg);
    let i6 = m * mp.kzz_m * mp.kzz_m;
    let mz = -m * ship.zg;
    let mut phi_a = 0.05;
    let mut bv = 0.0;
    let mut srt = [C::new(0.0, 0.0); 3];
    for _ in 0..50 {
        let c = components(&ship.roll, phi_a, we, u, rho, g);
        bv = if ship.viscous_roll_damping { c.iter().sum::<f64>() } else { 0.0 };
        srt = solve_small(
            [
                [z(m + a22, b22, 0.0), z(a24 + mz, b24, 0.0), z(a26, b26, 0.0)],
                [z(a24 + mz, b24, 0.0), z(i4 + a44, b44_pot + bv, c44), z(a46, b46, 0.0)],
                [z(a62, b62, 0.0), z(a64, b64, 0.0), z(i6 + a66, b66, 0.0)],
            ],
            [ex[0], ex[2], ex[4]],
        );
        let new = (srt[1].norm_sqr().sqrt() * roll_wave_amplitude).max(1e-4);
        if (new - phi_a).abs() < 1e-3 * phi_a {
            break;
        }
        phi_a = 0.5 * (phi_a + new);
    }
    let raos = [srt[0], hp[0], srt[1], hp[1], srt[2]];
    // Second-order mean force (eq. 2.47, Salvesen 1978) plus F7 (eq. 2.48, with sin^2 beta b22 beside
    // b33 and the mean section depth A/B as d_s). Salvesen writes Re{-(i/2) k conj(H_j)(F_j^I +
    // ^F_j^D)} with ^F^D the diffraction force of the conjugate incident wave; eq. 2.47 moves the
    // conjugate onto F^I only, which changes the diffraction term's real part. Its real part equals
    // Salvesen's when ^F^D is conjugated too, as here; the printed form does not vanish in long
    // waves (sigma_aw 1.0 at lambda/L = 4.8 and Fn 0.28, against 0.1 here and 0.01 by
    // Gerritsma-Beukelman).
    let mut s = 0.0;
    for j in 0..5 {
        // As printed (eq. 2.47): the conjugate on F^I only.
        let fd_j = if printed.eq_2_47_conjugate { fdh[j] } else { fdh[j].conj() };
        s += (C::new(0.0, 0.5 * k) * raos[j] * (fk[j].conj() + fd_j)).re;
    }
    // The short-wave part (`Ship::short_wave`). Eq. 2.48's F7 at encounter frequency for both
    // components; or the lit waterline's reflection (`reflection`) for the surge component, the
    // added resistance, and for the sway component F7 at zero speed (omega_e = omega0): in beam
    // seas, where a section that follows long waves has s + F7 near nothing, F7 is the
    // sections' own diffraction, which reflection by a thin wall of the local draft understates;
    // at zero speed it has no omega0 / omega_e to grow with in quartering seas.
    let f7_on = ship.short_wave == ShortWaveForce::SalvesenF7;
    let damping_0: Vec<(f64, f64)> =
        if f7_on { Vec::new() } else { (0..n).map(|i| table.damping_at(i, omega0)).collect() };
    let f7_density = |i: usize| -> f64 {
        let e = libm::exp(-2.0 * k * ship.strips[i].area / ship.strips[i].beam);
        if f7_on {
            0.5 * k * omega0 * omega0 / we * e * (secs[i].b33 + sb * sb * secs[i].b22)
        } else {
            let (b22, b33) = damping_0[i];
            0.5 * k * omega0 * e * (b33 + sb * sb * b22)
        }
    };
    let f7 = if f7_on {
        0.5 * k * omega0 * omega0 / we
            * int(&|i| {
                let ds = ship.strips[i].area / ship.strips[i].beam;
                libm::exp(-2.0 * k * ds) * (secs[i].b33 + sb * sb * secs[i].b22)
            })
    } else {
        int(&f7_density)
    };
    let surge_short = if f7_on {
        f7
    } else {
        let xs: Vec<f64> = ship.strips.iter().map(|s| s.xi).collect();
        let hb: Vec<f64> = ship.strips.iter().map(|s| 0.5 * s.beam).collect();
        let ts: Vec<f64> = ship.strips.iter().map(|s| s.draft).collect();
        reflection_force(&xs, &hb, &ts, k, omega0, u, beta, rho, g).0
    };
    let f_add = s + surge_short;
    let f_add_sway = s + f7;
    // The drift moment (see `response_as`): eq. 2.47's sum and eq. 2.48 strip by strip, each with
    // the lever xi sin(beta).
    let cj = |c: C| if printed.eq_2_47_conjugate { c } else { c.conj() };
    let [h2, h3, h4, h5, h6] = raos;
    let ik2 = C::new(0.0, 0.5 * k * rho);
    let share = |i: usize| -> f64 {
        let x = xi(i);
        let (d2, d3) = (h2 + h6 * x, h3 - h5 * x);
        let (fi, hi) = (f[i], hh[i]);
        let froude_krylov = d2 * fi[0].conj() + d3 * fi[1].conj() + h4 * fi[2].conj();
        let diffraction = d2 * cj(hi[0]) + d3 * cj(hi[1]) + h4 * cj(hi[2]) + cj(ui) * (h6 * cj(hi[0]) - h5 * cj(hi[1]));
        (ik2 * (froude_krylov + diffraction)).re + f7_density(i)
    };
    let transom = {
        let ha = hh[a];
        (ik2 * cj(ue) * ((h2 + h6 * xa) * cj(ha[0]) + (h3 - h5 * xa) * cj(ha[1]) + h4 * cj(ha[2]))).re
    };
    let unit_lever = int(&share) + transom;
    let drift_moment = sb * (int(&|i| xi(i) * share(i)) + xa * transom);
    // Gerritsma-Beukelman: R = -(k cos beta / 2 omega_e) int b'33 |V_z|^2 with the relative
    // vertical velocity including the Smith effect, b'33 = b33 - U da33/dx.
    let mut gb = 0.0;
    for i in 0..n {
        let st = &ship.strips[i];
        let da = if i == 0 {
            (secs[1].a33 - secs[0].a33) / (ship.strips[1].xi - st.xi)
        } else if i + 1 == n {
            (secs[i].a33 - secs[i - 1].a33) / (st.xi - ship.strips[i - 1].xi)
        } else {
            (secs[i + 1].a33 - secs[i - 1].a33) / (ship.strips[i + 1].xi - ship.strips[i - 1].xi)
        };
        let bprime = secs[i].b33 - u * da;
        let wave = cexp(C::new(0.0, -k * st.xi * cb)) * libm::exp(-k * st.area / st.beam);
        let vz = iw * (hp[0] - hp[1] * st.xi - wave);
        gb += st.weight * bprime * vz.norm_sqr();
    }
    let gb = -k * cb / (2.0 * we) * gb;
    let r = Response {
        omega0,
        omega_e: we,
        k,
        sway: raos[0],
        heave: raos[1],
        roll: raos[2],
        pitch: raos[3],
        yaw: raos[4],
        f_add,
        f_add_sway,
        added_resistance: -cb * f_add,
        drift_force: sb * f_add_sway,
        drift_moment,
        added_resistance_gb: gb,
        b44_viscous: bv,
    };
    let system = HeavePitchSystem {
        omega_e: we,
        mass: m,
        i55: i5,
        a33,
        b33,
        a35,
        b35,
        a53,
        b53,
        a55,
        b55,
        c33,
        c35,
        c55,
        x3_fk: fk[1],
        x3_d: fd[1],
        x5_fk: fk[3],
        x5_d: fd[3],
    };
    (r, unit_lever, system)
}

/// Zero-speed natural periods of heave and pitch \[s\] from the computed coefficients:
/// omega_n^2 = C / (M + A(omega_n)), solved by fixed-point iteration on the added mass.
pub fn natural_periods(ship: &Ship, table: &RadiationTable) -> (f64, f64) {
    let (rho, g) = (ship.rho, ship.g);
    let n = ship.strips.len();
    let int = |f: &dyn Fn(usize) -> f64| -> f64 { (0..n).map(|i| ship.strips[i].weight * f(i)).sum() };
    let c33 = rho * g * int(&|i| ship.strips[i].beam);
    let c55 = rho
        * g
        * (int(&|i| (ship.strips[i].xi * ship.strips[i].xi) * ship.strips[i].beam) + ship.volume * (ship.zb - ship.zg));
    let i5 = ship.mass * ((ship.mass_props.kyy_m * ship.mass_props.kyy_m) + ship.zg * ship.zg);
    let (mut w3, mut w5) = (1.0, 1.0);
    for _ in 0..100 {
        let a33 = int(&|i| table.at(i, w3).a33);
        let a55 = int(&|i| (ship.strips[i].xi * ship.strips[i].xi) * table.at(i, w5).a33);
        w3 = (c33 / (ship.mass + a33)).sqrt();
        w5 = (c55 / (i5 + a55)).sqrt();
    }
    (2.0 * std::f64::consts::PI / w3, 2.0 * std::f64::consts::PI / w5)
}

/// The heave-pitch equations of motion at one wave (unit amplitude): mass, the STF coefficients
/// at forward speed (Appendix A eqs. 4, 5, 8, 9, 16, 17, 20, 21, 31, 32, 34, without the printed
/// typos), the restoring coefficients, and the exciting force and moment on the restrained ship
/// (Froude-Krylov plus diffraction with its speed term), as [`response`] assembles them. SI units,
/// per metre of wave amplitude for the excitation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeavePitchSystem {
    pub omega_e: f64,
    pub mass: f64,
    pub i55: f64,
    pub a33: f64,
    pub b33: f64,
    pub a35: f64,
    pub b35: f64,
    pub a53: f64,
    pub b53: f64,
    pub a55: f64,
    pub b55: f64,
    pub c33: f64,
    pub c35: f64,
    pub c55: f64,
    /// Exciting heave force [N/m] and pitch moment [N m/m]: Froude-Krylov and diffraction parts.
    pub x3_fk: C,
    pub x3_d: C,
    pub x5_fk: C,
    pub x5_d: C,
}

/// [`HeavePitchSystem`] for the wave of frequency `omega0` at speed `u` and heading `beta`: the
/// coefficients and forces `response` solves, from the same computation.
pub fn heave_pitch_system(ship: &Ship, table: &RadiationTable, omega0: f64, u: f64, beta: f64) -> HeavePitchSystem {
    response_parts(ship, table, omega0, u, beta, 1.0, &AsPrintedParams::default()).2
}
