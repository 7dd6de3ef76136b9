//! Viscous roll damping by components (thesis eqs. 2.44-2.45; Ikeda, Himeno & Tanaka 1978):
//! hull friction (Kato 1958 with Tamiya's speed correction), eddy making and bilge keels (the
//! regressions of Ikeda's component method by Kawahara, Maekawa & Ikeda 2009, J. Marine Science
//! and Technology 14), and hull lift at forward speed (Ikeda). The wave component comes from the
//! strip theory itself. Each is returned as the equivalent linear coefficient B44* [N m s/rad]
//! that dissipates the same energy per cycle at roll amplitude `phi_a` (eq. 2.45). Powers and
//! exponentials go through libm (identical native and wasm numbers).

use std::f64::consts::PI;

/// What the component method needs to know about the hull.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollHull {
    /// Length, beam, draft \[m\], block and midship coefficients.
    pub lpp: f64,
    pub beam: f64,
    pub draft: f64,
    pub cb: f64,
    pub cm: f64,
    /// Height of the centre of gravity above the waterline \[m\] (OG in Ikeda's notation is its
    /// negative: distance below the waterline).
    pub zg: f64,
    /// Bilge keel length and breadth \[m\] (0 for none).
    pub bk_length: f64,
    pub bk_breadth: f64,
}

/// The viscous parts of B44* at roll amplitude `phi_a` \[rad\], frequency `omega` [rad/s], speed
/// `u` [m/s]: (friction, eddy, lift, bilge keel) [N m s/rad].
pub fn components(h: &RollHull, phi_a: f64, omega: f64, u: f64, rho: f64, g: f64) -> [f64; 4] {
    let (l, b, d, cb) = (h.lpp, h.beam, h.draft, h.cb);
    let nu_kin = 1.19e-6; // sea water at 15 C [m^2/s]
    let og = -h.zg; // Ikeda's OG, positive downward
    let ogd = og / d;
    let phi = phi_a.max(1e-4);
    let w = omega.max(1e-3);
    // Nondimensional damping B^ = B44 / (rho V B^2) sqrt(B / 2g), frequency w^ = w sqrt(B / 2g).
    let vol = l * b * d * cb;
    let to_dim = rho * vol * b * b / (b / (2.0 * g)).sqrt();
    let what = (w * (b / (2.0 * g)).sqrt()).min(1.0);
    // Friction (Kato): effective radius, wetted area, laminar skin friction at the roll Reynolds
    // number; Tamiya's factor for forward speed.
    let rf = d * ((0.887 + 0.145 * cb) * (1.7 + cb * b / d) - 2.0 * ogd) / PI;
    let sf = l * (1.75 * d + cb * b);
    let cf = 1.328 * libm::pow(3.22 * rf * rf * phi * phi * w / (2.0 * PI * nu_kin), -0.5);
    let bf = 4.0 / (3.0 * PI) * rho * sf * (rf * rf * rf) * phi * w * cf * (1.0 + 4.1 * u / (w * l));
    // Eddy making at zero speed (Kawahara et al. 2009 regression; valid for Cm 0.9-0.99, the
    // destroyer's 0.81 is taken at 0.9), reduced with speed by Ikeda's (0.04 K)^2 / (1 + (0.04 K)^2),
    // K = omega L / U.
    let cm = h.cm.clamp(0.9, 0.99);
    let bd = b / d;
    let fe1 = (-0.0182 * cb + 0.0155) * ((bd - 1.8) * (bd - 1.8) * (bd - 1.8));
    let fe2 = -79.414 * (cb * cb * cb * cb) + 215.695 * (cb * cb * cb) - 215.883 * cb * cb + 93.894 * cb - 14.848;
    let be1 = (3.98 * cb - 5.1525)
        * (-0.2 * bd + 1.6)
        * ogd
        * ((0.9717 * cb * cb - 1.55 * cb + 0.723) * ogd + 0.04567 * cb + 0.9408);
    let be2 = (0.25 * ogd + 0.95) * ogd - 219.2 * (cb * cb * cb) + 443.7 * cb * cb - 283.3 * cb + 59.6;
    let be3 = -15.0 * cb * bd + 46.5 * cb + 11.2 * bd - 28.6;
    let cr = (fe1 + fe2) * libm::exp(be1 + be2 * libm::pow(cm, be3));
    let be_hat = 4.0 * what * phi / (3.0 * PI * cb * (bd * bd * bd)) * cr;
    let speed_factor = if u > 1e-6 {
        let k = 0.04 * w * l / u;
        k * k / (1.0 + k * k)
    } else {
        1.0
    };
    let be = be_hat.max(0.0) * to_dim * speed_factor;
    // Lift of the hull as a low-aspect-ratio wing at forward speed (Ikeda).
    let kappa = if h.cm <= 0.92 {
        0.0
    } else if h.cm <= 0.97 {
        0.1
    } else {
        0.3
    };
    let kn = 2.0 * PI * d / l + kappa * (4.1 * b / l - 0.045);
    let (lo, lr) = (0.3 * d, 0.5 * d);
    let bl = 0.5 * rho * l * d * u * kn * lo * lr * (1.0 + 1.4 * og / lr + 0.7 * og * og / (lo * lr));
    // Bilge keels (Kawahara et al. 2009 regression of Ikeda's normal-force and hull-pressure
    // components; roll amplitude in degrees there).
    let bbk = if h.bk_length > 0.0 && h.bk_breadth > 0.0 {
        let (lbk, bbkb, phid) = (h.bk_length / l, h.bk_breadth / b, phi.to_degrees());
        let f1 = (-0.3651 * cb + 0.3907) * ((bd - 2.83) * (bd - 2.83)) - 2.21 * cb + 2.632;
        let f2 = 0.00255 * phid * phid + 0.122 * phid + 0.4794;
        let f3 = (-0.8913 * bbkb * bbkb - 0.0733 * bbkb) * lbk * lbk
            + (5.2857 * bbkb * bbkb - 0.01185 * bbkb + 0.00189) * lbk;
        let b1 = (5.0 * bbkb + 0.3 * bd - 0.2 * lbk + 0.00125 * phid * phid - 0.0425 * phid - 1.86) * ogd;
        let b2 = -15.0 * bbkb + 1.2 * cb - 0.1 * bd - 0.0657 * ogd * ogd + 0.0586 * ogd + 1.6164;
        let b3 = 2.5 * ogd + 15.75;
        (f1 * f2 * f3 * libm::exp(b1 + b2 * libm::pow(cm, b3)) * what).max(0.0) * to_dim
    } else {
        0.0
    };
    [bf, be, bl.max(0.0), bbk]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hull() -> RollHull {
        RollHull {
            lpp: 142.0,
            beam: 19.06,
            draft: 6.15,
            cb: 0.506,
            cm: 0.814,
            zg: 1.405,
            bk_length: 35.5,
            bk_breadth: 0.6,
        }
    }

    /// Each component is positive, friction grows with speed (Tamiya), eddy making falls with it
    /// (Ikeda), lift vanishes at rest, and the quadratic components scale with the amplitude
    /// (B44* of a damping delta |phi'| phi' is linear in phi_a, eq. 2.45).
    #[test]
    fn components_behave() {
        let h = hull();
        let c0 = components(&h, 0.1, 0.6, 0.0, 1025.0, 9.81);
        let c1 = components(&h, 0.1, 0.6, 12.9, 1025.0, 9.81);
        assert!(c0.iter().all(|&c| c >= 0.0) && c0[0] > 0.0 && c0[1] > 0.0 && c0[3] > 0.0 && c0[2] == 0.0, "{c0:?}");
        assert!(c1[0] > c0[0] && c1[1] < 0.2 * c0[1] && c1[2] > 0.0, "{c1:?}");
        let c2 = components(&h, 0.2, 0.6, 0.0, 1025.0, 9.81);
        // Eddy: linear in phi_a exactly.
        assert!((c2[1] / c0[1] - 2.0).abs() < 1e-9);
    }
}
