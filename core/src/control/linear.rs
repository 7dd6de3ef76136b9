//! The linear-systems toolkit: a single-input single-output model x' = A x + B u, y = C x + D u
//! with its poles and Bode points, logarithmic frequency grids, the crossings of a loop's Nyquist
//! curve and the classical margins read from them. The IPS stability tool of ch. 4
//! (`studies::ips`) and the controller design of ch. 3.1 (`control::design`) both rest on it.

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;
use serde::Serialize;

/// A linear time-invariant model dx/dt = A x + B u, y = C x + D u (single input, single output).
#[derive(Debug, Clone, PartialEq)]
pub struct LinearSystem {
    pub a: DMatrix<f64>,
    pub b: DMatrix<f64>,
    pub c: DMatrix<f64>,
    pub d: DMatrix<f64>,
    /// Names of the states, in order.
    pub states: Vec<&'static str>,
}

/// One eigenvalue with its damping ratio and natural frequency.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Pole {
    pub re: f64,
    pub im: f64,
    /// Damping ratio -re/|lambda| [-].
    pub damping: f64,
    /// Natural frequency |lambda| [rad/s].
    pub natural_frequency_rad_s: f64,
}

impl Pole {
    /// The pole of eigenvalue `l`: damping -re/|l| (1 at the origin), natural frequency |l|.
    pub fn of(l: Complex64) -> Pole {
        let w = cabs(l);
        Pole { re: l.re, im: l.im, damping: if w > 0.0 { -l.re / w } else { 1.0 }, natural_frequency_rad_s: w }
    }
}

/// Sorts poles by real part, then imaginary part (least stable last).
pub fn sort_poles(poles: &mut [Pole]) {
    poles.sort_by(|a, b| a.re.total_cmp(&b.re).then(a.im.total_cmp(&b.im)));
}

/// One point of a frequency response.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BodePoint {
    pub omega_rad_s: f64,
    pub magnitude_db: f64,
    pub phase_deg: f64,
}

impl LinearSystem {
    /// Checks that every entry of A, B, C, D is finite (a model built from an extreme operating
    /// point can overflow); the error names the matrix and the entry.
    pub fn check_finite(&self) -> Result<(), String> {
        for (name, m) in [("A", &self.a), ("B", &self.b), ("C", &self.c), ("D", &self.d)] {
            if let Some(k) = m.iter().position(|x| !x.is_finite()) {
                let (i, j) = (k % m.nrows(), k / m.nrows());
                return Err(format!(
                    "the linear model's {name}[{i}][{j}] = {} is not finite: the operating point or the parameters are outside what the model can represent",
                    m[(i, j)]
                ));
            }
        }
        Ok(())
    }

    /// Eigenvalues of A, sorted by real part (least stable last). The QR iteration is bounded
    /// ([`MAX_SCHUR_ITERATIONS`]); a non-finite A or a decomposition that does not converge is an
    /// error, never a hang.
    pub fn poles(&self) -> Result<Vec<Pole>, String> {
        self.check_finite()?;
        let n = self.a.nrows();
        let schur = nalgebra::linalg::Schur::try_new(self.a.clone(), f64::EPSILON, MAX_SCHUR_ITERATIONS)
            .ok_or_else(|| format!("the eigenvalues of the {n}x{n} linear model did not converge"))?;
        let ev = schur.complex_eigenvalues();
        let mut poles: Vec<Pole> = ev.iter().map(|&l| Pole::of(l)).collect();
        if poles.iter().any(|p| !(p.re.is_finite() && p.im.is_finite() && p.natural_frequency_rad_s.is_finite())) {
            return Err(format!("the eigenvalues of the {n}x{n} linear model are not finite"));
        }
        sort_poles(&mut poles);
        Ok(poles)
    }

    /// Whether every pole has a negative real part.
    pub fn is_stable(&self) -> Result<bool, String> {
        Ok(self.poles()?.iter().all(|p| p.re < 0.0))
    }

    /// G(j omega) = C (j omega I - A)^-1 B + D.
    pub fn response(&self, omega: f64) -> Complex64 {
        let n = self.a.nrows();
        let m = DMatrix::<Complex64>::from_fn(n, n, |i, j| {
            let v = -self.a[(i, j)];
            Complex64::new(v, if i == j { omega } else { 0.0 })
        });
        let b = DVector::<Complex64>::from_fn(n, |i, _| Complex64::new(self.b[(i, 0)], 0.0));
        let x = m.lu().solve(&b).unwrap_or_else(|| DVector::from_element(n, Complex64::new(f64::NAN, f64::NAN)));
        let mut g = Complex64::new(self.d[(0, 0)], 0.0);
        for i in 0..n {
            g += self.c[(0, i)] * x[i];
        }
        g
    }

    /// Bode points at the given frequencies [rad/s]; an error (naming the frequency) where the
    /// response is not finite (a pole on the axis, or a model that overflows).
    pub fn bode(&self, omegas: &[f64]) -> Result<Vec<BodePoint>, String> {
        self.check_finite()?;
        omegas
            .iter()
            .map(|&w| {
                let g = self.response(w);
                let p = BodePoint {
                    omega_rad_s: w,
                    magnitude_db: 20.0 * libm::log10(cabs(g)),
                    phase_deg: carg(g).to_degrees(),
                };
                if p.magnitude_db.is_finite() && p.phase_deg.is_finite() {
                    Ok(p)
                } else {
                    Err(format!("the frequency response at {w} rad/s is not finite (|G| = {})", cabs(g)))
                }
            })
            .collect()
    }

    /// The public form (`aes-sim ips linear`'s `linear`): matrices as arrays of rows, poles,
    /// state names.
    pub fn report(&self) -> Result<LinearReport, String> {
        let poles = self.poles()?;
        let stable = poles.iter().all(|p| p.re < 0.0);
        let rows = |m: &DMatrix<f64>| -> Vec<Vec<f64>> {
            (0..m.nrows()).map(|i| (0..m.ncols()).map(|j| m[(i, j)]).collect()).collect()
        };
        Ok(LinearReport {
            states: self.states.clone(),
            a: rows(&self.a),
            b: rows(&self.b),
            c: rows(&self.c),
            d: rows(&self.d),
            poles,
            stable,
        })
    }
}

/// A linear model as the IPS tool reports it: state names, A, B, C, D as arrays of rows, the poles
/// (least stable last) and whether every one is in the left half plane.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LinearReport {
    pub states: Vec<&'static str>,
    pub a: Vec<Vec<f64>>,
    pub b: Vec<Vec<f64>>,
    pub c: Vec<Vec<f64>>,
    pub d: Vec<Vec<f64>>,
    pub poles: Vec<Pole>,
    pub stable: bool,
}

/// Most QR iterations the eigenvalue solver may take (the models have at most 12 states and
/// converge in well under 100).
pub const MAX_SCHUR_ITERATIONS: usize = 10_000;

/// |z| through libm (num-complex's `norm` calls the platform's hypot, which differs native vs wasm).
fn cabs(z: Complex64) -> f64 {
    libm::hypot(z.re, z.im)
}

/// arg z in (-pi, pi] through libm (num-complex's `arg` calls the platform's atan2).
fn carg(z: Complex64) -> f64 {
    libm::atan2(z.im, z.re)
}

/// Logarithmically spaced frequencies from `from` to `to` [rad/s], `n` points.
pub fn log_space(from: f64, to: f64, n: usize) -> Vec<f64> {
    let (a, b) = (libm::log(from), libm::log(to));
    (0..n).map(|i| libm::exp(a + (b - a) * i as f64 / (n.max(2) - 1) as f64)).collect()
}

/// Gain and phase of a simulated sinusoidal response: the output's component at `omega` over a
/// whole number of periods, divided by the input amplitude's.
pub fn fourier_gain(t: &[f64], y: &[f64], omega: f64, input_amplitude: f64) -> BodePoint {
    let (mut s, mut c) = (0.0, 0.0);
    for i in 1..t.len() {
        let dt = t[i] - t[i - 1];
        let ym = 0.5 * (y[i] + y[i - 1]);
        let tm = 0.5 * (t[i] + t[i - 1]);
        s += ym * libm::sin(omega * tm) * dt;
        c += ym * libm::cos(omega * tm) * dt;
    }
    let span = t[t.len() - 1] - t[0];
    let (a_sin, a_cos) = (2.0 * s / span, 2.0 * c / span);
    // Input u = A sin(omega t): y = |G| A sin(omega t + phi) = |G| A (sin cos phi + cos sin phi).
    let g = Complex64::new(a_sin, a_cos) / input_amplitude;
    BodePoint { omega_rad_s: omega, magnitude_db: 20.0 * libm::log10(cabs(g)), phase_deg: carg(g).to_degrees() }
}

/// Classical stability margins of a loop transfer function L(j omega) (negative feedback).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Margins {
    /// Gain margin \[dB\] at the lowest phase crossover (L real and negative); None if none.
    pub gain_margin_db: Option<f64>,
    pub phase_crossover_rad_s: Option<f64>,
    /// Phase margin \[deg\] at the lowest gain crossover (|L| = 1); None if none.
    pub phase_margin_deg: Option<f64>,
    pub gain_crossover_rad_s: Option<f64>,
}

/// Where a loop's Nyquist curve L(j omega) crosses the unit circle or the real axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Crossing {
    /// |L| = 1 at `w` [rad/s].
    Gain { w: f64, l: Complex64 },
    /// Im L = 0 at `w` [rad/s] (a phase crossover when Re L < 0).
    Phase { w: f64, l: Complex64 },
}

/// Every crossing of `l` between neighbouring points of `grid` [rad/s], in frequency order, each
/// refined by `bisections` halvings (of the log frequency). An error from `l` stops the search.
pub fn crossings(
    l: &dyn Fn(f64) -> Result<Complex64, String>,
    grid: &[f64],
    bisections: usize,
) -> Result<Vec<Crossing>, String> {
    let refine = |a: f64, b: f64, g: &dyn Fn(Complex64) -> f64| -> Result<f64, String> {
        let (mut a, mut b) = (a, b);
        let ga = g(l(a)?);
        for _ in 0..bisections {
            let m = libm::sqrt(a * b);
            if (g(l(m)?) > 0.0) == (ga > 0.0) {
                a = m;
            } else {
                b = m;
            }
        }
        Ok(libm::sqrt(a * b))
    };
    let mag = |z: Complex64| cabs(z) - 1.0;
    let im = |z: Complex64| z.im;
    let vals: Vec<Complex64> = grid.iter().map(|&w| l(w)).collect::<Result<_, _>>()?;
    let mut out = Vec::new();
    for k in 1..grid.len() {
        let (a, b) = (grid[k - 1], grid[k]);
        if (mag(vals[k - 1]) > 0.0) != (mag(vals[k]) > 0.0) {
            let w = refine(a, b, &mag)?;
            out.push(Crossing::Gain { w, l: l(w)? });
        }
        if (im(vals[k - 1]) > 0.0) != (im(vals[k]) > 0.0) {
            let w = refine(a, b, &im)?;
            out.push(Crossing::Phase { w, l: l(w)? });
        }
    }
    Ok(out)
}

/// Margins of `l` searched on a logarithmic grid from `w_lo` to `w_hi` [rad/s], crossings refined
/// by bisection: the lowest gain crossover and the lowest phase crossover.
pub fn margins(l: &dyn Fn(f64) -> Complex64, w_lo: f64, w_hi: f64) -> Margins {
    let mut out = Margins {
        gain_margin_db: None,
        phase_crossover_rad_s: None,
        phase_margin_deg: None,
        gain_crossover_rad_s: None,
    };
    let found = crossings(&|w| Ok(l(w)), &log_space(w_lo, w_hi, 4000), 100).unwrap_or_default();
    for c in found {
        match c {
            Crossing::Gain { w, l } if out.gain_crossover_rad_s.is_none() => {
                let mut pm = carg(l).to_degrees() + 180.0;
                if pm > 180.0 {
                    pm -= 360.0;
                }
                out.gain_crossover_rad_s = Some(w);
                out.phase_margin_deg = Some(pm);
            }
            Crossing::Phase { w, l } if out.phase_crossover_rad_s.is_none() && l.re < 0.0 => {
                out.phase_crossover_rad_s = Some(w);
                out.gain_margin_db = Some(-20.0 * libm::log10(cabs(l)));
            }
            _ => {}
        }
    }
    out
}
