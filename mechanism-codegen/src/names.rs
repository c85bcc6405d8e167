//! Stage 0, names: the families of identifiers the generated code builds
//! from the user's names (`vel_B`, `in_theta`, `rx_C`, ...), each with its
//! prefix. Code that builds such a name asks its family
//! ([`Family::of`]); the names a user may not take
//! ([`reserved_prefixes`]) are derived from the same list.

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
}

impl Family {
    /// Every family.
    pub const ALL: [Family; 15] = [
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
        }
    }

    /// `true` when a user's name may not begin with its prefix: the
    /// families of locals that share a scope with the user's names (the
    /// batch columns and `pos_` live in their own structs and scopes).
    pub const fn reserved(self) -> bool {
        !matches!(
            self,
            Family::Pos | Family::In | Family::Rate | Family::Accel
        )
    }

    /// `PREFIX_name`, on `name`'s span (a raw identifier's `r#` left out,
    /// as `format_ident!` does).
    pub fn of(self, name: &Ident) -> Ident {
        quote::format_ident!("{}_{}", self.stem(), name)
    }

    /// `PREFIX_name` for a name held as text, on the call site.
    pub fn named(self, name: &str) -> Ident {
        quote::format_ident!("{}_{}", self.stem(), name)
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
