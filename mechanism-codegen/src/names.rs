//! Stage 0, names: the families of identifiers the generated code builds
//! from the user's names (`vel_B`, `in_theta`, `rx_C`, `r_link2_link3`,
//! ...), each with its prefix. Code that builds such a name asks its family
//! ([`Family::of`], [`Family::pair`], or [`Family::text`] for a name held as
//! text); the names a user may not take ([`reserved_prefixes`]) are derived
//! from the same list.

use quote::IdentFragment;
use std::fmt::Display;
use syn::Ident;

/// A family of generated identifiers: `PREFIX_NAME`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    /// `pos_NAME`: a point's (or guide's, link angle's, slide's) local in
    /// the position code; a batch's position output column.
    Pos,
    /// `vel_NAME`: a velocity local, a batch's velocity output column.
    Vel,
    /// `acc_NAME`: an acceleration local, a batch's acceleration column.
    Acc,
    /// `grp_NAME`: a statement's solved position state.
    Grp,
    /// `axis_LINK`: a link's unit axis.
    Axis,
    /// `omega_LINK`: a link's angular velocity local.
    Omega,
    /// `alpha_LINK`: a link's angular acceleration local.
    Alpha,
    /// `gvel_GUIDE`: a carried guide's velocity.
    Gvel,
    /// `gacc_GUIDE`: a carried guide's acceleration.
    Gacc,
    /// `load_LINK`: a link's known load in the force code.
    Load,
    /// `rx_NAME`: a statement's reactions in the force code.
    Rx,
    /// `pw_...`: a power term.
    Pw,
    /// `in_INPUT`: a batch's input column.
    In,
    /// `rate_INPUT`: a batch's input rate column.
    Rate,
    /// `accel_INPUT`: a batch's input acceleration column.
    Accel,
    /// `grp_v_NAME`: a statement's solved velocity state.
    GrpVel,
    /// `grp_a_NAME`: a statement's solved acceleration state.
    GrpAcc,
    /// `rx_axis_NAME`: an actuator's axis in the force code.
    RxAxis,
    /// `pw_inertia_couple_LINK`: a link's inertia couple.
    PwInertiaCouple,
    /// `pw_inertia_force_PART`: a mass part's inertia force.
    PwInertiaForce,
    /// `pw_weight_PART`: a mass part's weight.
    PwWeight,
    /// `pw_force_K`: external force number `K`.
    PwForce,
    /// `pw_torque_K`: external couple number `K`.
    PwTorque,
    /// `pw_m_PART`: a mass checked at run time.
    PwMass,
    /// `pw_j_PART`: a moment of inertia checked at run time.
    PwInertia,
    /// `dyn_m_PART`: a mass checked at run time in the dynamics code.
    DynMass,
    /// `dyn_j_PART`: a moment of inertia checked there.
    DynInertia,
    /// `c_I_K`: an entry of the dynamics code's coefficient matrix (by
    /// indices, no user's name).
    Coef,
    /// `r_FROM_TO`: the forces struct's field of a joint's reaction, the
    /// force on `TO` from `FROM` (`ground` for the ground).
    Reaction,
    /// `drive_INPUT`: the forces struct's field of a driver's (or motor's)
    /// effort.
    Drive,
    /// `m_GROUND_LINK`: the forces struct's field of the couple holding a
    /// target's effector.
    Mount,
    /// `m_NAME`: the batch kernel's sign of a run-time mode.
    LaneSign,
    /// `g_NAME`: the batch kernel's group state.
    LaneGroup,
    /// `w_LINK`: the batch kernel's angular velocity of a link.
    LaneOmega,
    /// `al_LINK`: the batch kernel's angular acceleration of a link.
    LaneAlpha,
    /// `u_NAME`: the batch kernel's unit vector computed before the loop.
    LaneUnit,
    /// `gv_NAME`: the batch kernel's carried guide's velocity.
    LaneGuideVel,
    /// `ga_NAME`: the batch kernel's carried guide's acceleration.
    LaneGuideAcc,
    /// `lp_NAME`: the batch kernel's link point offset computed before the
    /// loop.
    LaneLinkPoint,
    /// `ln_NAME`: the batch kernel's guide line.
    LaneLine,
    /// `p_NAME_x`, `p_NAME_y`: the batch kernel's point position.
    LanePos,
    /// `v_NAME_x`, `v_NAME_y`: the batch kernel's point velocity.
    LaneVel,
    /// `a_NAME_x`, `a_NAME_y`: the batch kernel's point acceleration.
    LaneAcc,
    /// `o_NAME_x`, `o_NAME_y`: the batch kernel's link point offset from
    /// its reference point.
    LaneOffset,
}

impl Family {
    /// Every family.
    pub const ALL: [Family; 44] = [
        Family::Pos,
        Family::Vel,
        Family::Acc,
        Family::Grp,
        Family::Axis,
        Family::Omega,
        Family::Alpha,
        Family::Gvel,
        Family::Gacc,
        Family::Load,
        Family::Rx,
        Family::Pw,
        Family::In,
        Family::Rate,
        Family::Accel,
        Family::GrpVel,
        Family::GrpAcc,
        Family::RxAxis,
        Family::PwInertiaCouple,
        Family::PwInertiaForce,
        Family::PwWeight,
        Family::PwForce,
        Family::PwTorque,
        Family::PwMass,
        Family::PwInertia,
        Family::DynMass,
        Family::DynInertia,
        Family::Coef,
        Family::Reaction,
        Family::Drive,
        Family::Mount,
        Family::LaneSign,
        Family::LaneGroup,
        Family::LaneOmega,
        Family::LaneAlpha,
        Family::LaneUnit,
        Family::LaneGuideVel,
        Family::LaneGuideAcc,
        Family::LaneLinkPoint,
        Family::LaneLine,
        Family::LanePos,
        Family::LaneVel,
        Family::LaneAcc,
        Family::LaneOffset,
    ];

    /// The batch's input columns by level (value, rate, acceleration).
    pub const BATCH_INPUTS: [Family; 3] = [Family::In, Family::Rate, Family::Accel];

    /// Its prefix, without the `_`.
    pub const fn stem(self) -> &'static str {
        match self {
            Family::Pos => "pos",
            Family::Vel => "vel",
            Family::Acc => "acc",
            Family::Grp => "grp",
            Family::Axis => "axis",
            Family::Omega => "omega",
            Family::Alpha => "alpha",
            Family::Gvel => "gvel",
            Family::Gacc => "gacc",
            Family::Load => "load",
            Family::Rx => "rx",
            Family::Pw => "pw",
            Family::In => "in",
            Family::Rate => "rate",
            Family::Accel => "accel",
            Family::GrpVel => "grp_v",
            Family::GrpAcc => "grp_a",
            Family::RxAxis => "rx_axis",
            Family::PwInertiaCouple => "pw_inertia_couple",
            Family::PwInertiaForce => "pw_inertia_force",
            Family::PwWeight => "pw_weight",
            Family::PwForce => "pw_force",
            Family::PwTorque => "pw_torque",
            Family::PwMass => "pw_m",
            Family::PwInertia => "pw_j",
            Family::DynMass => "dyn_m",
            Family::DynInertia => "dyn_j",
            Family::Coef => "c",
            Family::Reaction => "r",
            Family::Drive => "drive",
            Family::Mount => "m",
            Family::LaneSign => "m",
            Family::LaneGroup => "g",
            Family::LaneOmega => "w",
            Family::LaneAlpha => "al",
            Family::LaneUnit => "u",
            Family::LaneGuideVel => "gv",
            Family::LaneGuideAcc => "ga",
            Family::LaneLinkPoint => "lp",
            Family::LaneLine => "ln",
            Family::LanePos => "p",
            Family::LaneVel => "v",
            Family::LaneAcc => "a",
            Family::LaneOffset => "o",
        }
    }

    /// `true` when a user's name may not begin with its prefix: the
    /// families of locals that share a scope with the user's names. The
    /// batch columns and `pos_` live in their own structs and scopes; the
    /// forces struct's fields (`r_`, `drive_`, `m_`) in theirs; the batch
    /// kernel's locals in the kernel, where every name is prefixed; the
    /// coefficients `c_I_K` carry no name; the families whose stem begins
    /// with a reserved one (`grp_v`, `rx_axis`, `pw_..`) are covered by it;
    /// `dyn_m`, `dyn_j` are locals of the dynamics method alone.
    pub const fn reserved(self) -> bool {
        matches!(
            self,
            Family::Vel
                | Family::Acc
                | Family::Grp
                | Family::Axis
                | Family::Omega
                | Family::Alpha
                | Family::Gvel
                | Family::Gacc
                | Family::Load
                | Family::Rx
                | Family::Pw
        )
    }

    /// `PREFIX_name`, on `name`'s span when it is an identifier (a raw
    /// identifier's `r#` left out, as `format_ident!` does), else on the
    /// call site.
    pub fn of(self, name: impl IdentFragment) -> Ident {
        quote::format_ident!("{}_{}", self.stem(), name)
    }

    /// `PREFIX_name` for a name held as text, on the call site.
    pub fn named(self, name: &str) -> Ident {
        quote::format_ident!("{}_{}", self.stem(), name)
    }

    /// `PREFIX_a_b`: a name of two parts (a joint's two bodies, a matrix
    /// entry's indices), on `a`'s span when it is an identifier.
    pub fn pair(self, a: impl IdentFragment, b: impl IdentFragment) -> Ident {
        quote::format_ident!("{}_{}_{}", self.stem(), a, b)
    }

    /// `PREFIX_name_axis`: one coordinate (`axis` `x` or `y`) of a point's
    /// name, on `name`'s span when it is an identifier.
    pub fn coord(self, name: impl IdentFragment, axis: &str) -> Ident {
        quote::format_ident!("{}_{}_{}", self.stem(), name, axis)
    }

    /// The family of a rate level's motions: `vel_` in velocity (`accel`
    /// false), `acc_` in acceleration.
    pub const fn motion(accel: bool) -> Family {
        if accel {
            Family::Acc
        } else {
            Family::Vel
        }
    }

    /// The family of a rate level's link rates: `omega_` or `alpha_`.
    pub const fn link_rate(accel: bool) -> Family {
        if accel {
            Family::Alpha
        } else {
            Family::Omega
        }
    }

    /// `PREFIX_name` as text (the run-time evaluator's field names).
    pub fn text(self, name: impl Display) -> String {
        format!("{}_{}", self.stem(), name)
    }

    /// `PREFIX_a_b` as text.
    pub fn pair_text(self, a: impl Display, b: impl Display) -> String {
        format!("{}_{}_{}", self.stem(), a, b)
    }
}

/// The prefixes (with their `_`) a user's name may not begin with.
pub fn reserved_prefixes() -> impl Iterator<Item = String> {
    Family::ALL
        .into_iter()
        .filter(|f| f.reserved())
        .map(|f| format!("{}_", f.stem()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_reserved_prefixes_are_the_local_families() {
        // Proves the derived list holds exactly the prefixes of the locals
        // that share the user's scope, each once.
        let got: Vec<String> = reserved_prefixes().collect();
        let want = [
            "vel_", "acc_", "grp_", "axis_", "omega_", "alpha_", "gvel_", "gacc_", "load_", "rx_",
            "pw_",
        ];
        assert_eq!(got, want);
    }
}
