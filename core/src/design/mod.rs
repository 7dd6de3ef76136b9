//! Controller design (thesis ch. 3.1): LQG with loop transfer recovery for any linear plant
//! (A, B, C, D), the Riccati equations it rests on, and the loop and closed-loop analysis of
//! eqs. 3.2-3.10 (`aes-sim design lqg-ltr`).

pub mod lqg_ltr;
pub mod riccati;
