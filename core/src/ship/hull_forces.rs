//! The hull's hydrodynamic forces as both maneuvering models give them (Table 2.3's and the
//! hull's own): what the equations of motion add to thrust, rudder and waves.

/// Hydrodynamic hull forces \[N\] and yaw moment [N m] (the f of eq. 2.20 without thrust and rudder).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct HullForces {
    pub x: f64,
    pub y: f64,
    pub n: f64,
    /// The straight-running part of `x`: q (X_0 + X_u du + X_uu du^2 + X_uuu du^3) \[N\], the
    /// kayak's resistance curve of Table 2.3 (the rest of `x` comes from sway and yaw); 0 in the
    /// hull's own model, whose straight-line resistance is eq. 2.15's.
    pub x_straight: f64,
}
