//! Typed keys for the user's names: one newtype per family of names a
//! definition defines (points, links, guides, slides, inputs) and [`Name`]
//! for a name of any family (what a statement defines, whatever it is).
//!
//! The plan ([`crate::plan::Plan`]) and the stages after it key their maps by
//! these, so a map says what it holds and a point's name cannot be looked up
//! among the links: `plan.links.get(&PointName::of(p))` does not compile.
//! A key is made from the user's token ([`PointName::of`]) or, for a name
//! held as text (a run-time parameter list, a test), from its text
//! ([`PointName::new`]); the family is always said where the key is made.
//! The keys do not borrow as `str` (no `Borrow<str>`), for the same reason:
//!
//! ```
//! use mechanism_codegen::keys::LinkName;
//! use std::collections::BTreeMap;
//! let links: BTreeMap<LinkName, u32> = [(LinkName::new("link2"), 2)].into();
//! assert_eq!(links.get(&LinkName::new("link2")), Some(&2));
//! ```
//!
//! ```compile_fail,E0308
//! use mechanism_codegen::keys::{LinkName, PointName};
//! use std::collections::BTreeMap;
//! let links: BTreeMap<LinkName, u32> = [(LinkName::new("link2"), 2)].into();
//! links.get(&PointName::new("link2")); // a point's name among the links
//! ```
//!
//! ```compile_fail,E0277
//! use mechanism_codegen::keys::LinkName;
//! use std::collections::BTreeMap;
//! let links: BTreeMap<LinkName, u32> = [(LinkName::new("link2"), 2)].into();
//! links.get("link2"); // untyped text
//! ```
//!
//! Each key holds the name as written (a `String`): the maps are small
//! (one entry per statement), built once per expansion, and a key's text is
//! what the diagnostics and the generated identifiers need.

use quote::{format_ident, IdentFragment};
use std::fmt;
use syn::Ident;

/// The fixed frame's name where a link is written (`ground` as a guide's or
/// gear's carrier, a motor's reaction body, the `ground` in the field
/// `r_ground_link2`): a word the language reserves, never a moving link's.
pub const GROUND: &str = "ground";

/// Declares a key newtype over the name's text, with its constructors, its
/// text, its identifier and its formatting.
macro_rules! key {
    ($(#[$doc:meta])* $key:ident) => {
        $(#[$doc])*
        #[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
        pub struct $key(String);

        impl $key {
            /// The key of the user's name `ident`.
            pub fn of(ident: &Ident) -> Self {
                Self(ident.to_string())
            }

            /// The key of a name held as text.
            pub fn new(name: impl Into<String>) -> Self {
                Self(name.into())
            }

            /// The name as written.
            pub fn as_str(&self) -> &str {
                &self.0
            }

            /// The name as an identifier (call-site span), for generated code.
            pub fn ident(&self) -> Ident {
                format_ident!("{}", self.0)
            }

            /// The same name as a key of any family (for [`Name`] maps).
            pub fn name(&self) -> Name {
                Name(self.0.clone())
            }
        }

        impl fmt::Display for $key {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str(&self.0)
            }
        }

        impl IdentFragment for $key {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str(&self.0)
            }
        }

        /// The key's text is `other` (a name held as text, a test).
        impl PartialEq<&str> for $key {
            fn eq(&self, other: &&str) -> bool {
                self.0 == *other
            }
        }

        /// The user's token names this key (`ident == key`).
        impl PartialEq<Ident> for $key {
            fn eq(&self, other: &Ident) -> bool {
                other == self.0.as_str()
            }
        }
    };
}

key! {
    /// A point's name: a statement that defines a point (`let B = rrr(..)`),
    /// ground points included.
    PointName
}

key! {
    /// A link's name: one of the links a statement creates (`as (link3,
    /// link4)`, or the generated name of an unnamed one).
    LinkName
}

key! {
    /// A guide's name: a statement that defines a line (`let g = guide(..)`).
    GuideName
}

key! {
    /// A slide displacement's name: an RPR's defined name, or a name given
    /// to one of a statement's slides.
    SlideName
}

key! {
    /// A driver input's name (`theta` in `crank(O2, r, theta)`).
    InputName
}

key! {
    /// A name of any family: what a statement defines (its point, guide or
    /// slide) or one of the links it creates. Maps that a reference of any
    /// role is looked up in (which statement defines a name) are keyed by it.
    Name
}
