//! Scalar expressions in a definition: literals, parameters, constants and
//! arithmetic on them, with angle units. Constant sub-expressions are folded at
//! expansion time, so `const` values and literals cost nothing at run time.

use proc_macro2::{Span, TokenStream};
use quote::{quote, quote_spanned};
use syn::spanned::Spanned;
use syn::{BinOp, Expr, Ident, Lit, UnOp};

/// A scalar expression with its span.
#[derive(Clone, Debug)]
pub struct Value {
    /// What it is.
    pub kind: ValueKind,
    /// The span of the user's first token.
    pub span: Span,
    /// The user's tokens (for errors that cover the whole expression).
    pub tokens: TokenStream,
}

/// The shapes a scalar expression can take.
#[derive(Clone, Debug)]
pub enum ValueKind {
    /// A number (constants are folded into this).
    Lit(f64),
    /// A run-time parameter `self.name`.
    Param(Ident),
    /// A per-evaluation load value `loads.name` (force analysis only).
    Load(Ident),
    /// `-x`.
    Neg(Box<Value>),
    /// `x op y` with `op` one of `+ - * /`.
    Bin(Box<Value>, char, Box<Value>),
}

impl Value {
    /// A literal with a span.
    pub fn lit(x: f64, span: Span) -> Self {
        Value {
            kind: ValueKind::Lit(x),
            span,
            tokens: quote_spanned!(span=> #x),
        }
    }

    /// The number, when the expression depends on literals and constants only.
    pub fn fold(&self) -> Option<f64> {
        match &self.kind {
            ValueKind::Lit(x) => Some(*x),
            ValueKind::Param(_) | ValueKind::Load(_) => None,
            ValueKind::Neg(v) => v.fold().map(|x| -x),
            ValueKind::Bin(a, op, b) => {
                let (a, b) = (a.fold()?, b.fold()?);
                Some(match op {
                    '+' => a + b,
                    '-' => a - b,
                    '*' => a * b,
                    _ => a / b,
                })
            }
        }
    }

    /// Multiplies by `pi / 180` (for `deg`).
    pub fn degrees(self) -> Self {
        let span = self.span;
        match self.fold() {
            Some(x) => Value::lit(x.to_radians(), span),
            None => {
                let tokens = self.tokens.clone();
                Value {
                    kind: ValueKind::Bin(
                        Box::new(self),
                        '*',
                        Box::new(Value::lit(core::f64::consts::PI / 180.0, span)),
                    ),
                    span,
                    tokens,
                }
            }
        }
    }

    /// Rust code computing the value in the scalar type `T` (inside a method
    /// with `self` the parameter struct). Folded values become one literal.
    pub fn emit(&self) -> TokenStream {
        if let Some(x) = self.fold() {
            return lit(x);
        }
        match &self.kind {
            ValueKind::Lit(x) => lit(*x),
            ValueKind::Param(name) => quote_spanned!(self.span=> self.#name),
            ValueKind::Load(name) => quote_spanned!(self.span=> loads.#name),
            ValueKind::Neg(v) => {
                let v = v.emit();
                quote!((-#v))
            }
            ValueKind::Bin(a, op, b) => {
                let (a, b) = (a.emit(), b.emit());
                match op {
                    '+' => quote!((#a + #b)),
                    '-' => quote!((#a - #b)),
                    '*' => quote!((#a * #b)),
                    _ => quote!((#a / #b)),
                }
            }
        }
    }
}

/// `T::lit(x)` with `x` printed exactly (shortest round-trip form). Every
/// number the front end folds is checked finite on the user's tokens
/// ([`convert`]); a non-finite `x` here would be a bug of the code generator,
/// so it becomes a compile error rather than a panic of the macro.
pub fn lit(x: f64) -> TokenStream {
    if !x.is_finite() {
        let message = format!("mechanism! internal error: the non-finite number {x} reached the generated code; please report this definition");
        return quote!(::core::compile_error!(#message));
    }
    let literal = proc_macro2::Literal::f64_suffixed(x);
    quote!(<T as ::mechanism::Real>::lit(#literal))
}

/// An error when `v`, a node just built by [`convert`] whose operands were
/// checked already, folds to a number that is not finite: a literal too
/// large for `f64`, a division by an expression that folds to zero, or a
/// folded operation that overflows or gives NaN. The check runs on every
/// sub-expression, so `r + 1e308 * 10.0` with `r` a parameter is an error
/// on `1e308 * 10.0` wherever it stands (a dimension, a load, gravity, an
/// angle, a torque).
fn check_finite(v: &Value) -> Result<(), syn::Error> {
    let folded = v.fold();
    let message = match (&v.kind, folded) {
        (ValueKind::Bin(_, '/', b), _) if b.fold() == Some(0.0) => format!(
            "division by zero: `{}` is 0, so this is not a finite number; dimensions must be finite",
            b.tokens
        ),
        (ValueKind::Lit(x), _) if !x.is_finite() => format!(
            "`{}` is not a finite number (too large for an f64, it rounds to {x}); dimensions must be finite",
            v.tokens
        ),
        (_, Some(x)) if !x.is_finite() => format!(
            "`{}` evaluates to {x}, not a finite number (it overflows an f64); every number in a definition must be finite",
            v.tokens
        ),
        _ => return Ok(()),
    };
    Err(syn::Error::new_spanned(&v.tokens, message))
}

/// An error for a number written with a type suffix (`1u8`, `1.5f32`) or in
/// another base (`0x10`, `0b1`, `0o7`): the language takes plain decimal
/// numbers, whose type is the mechanism's scalar `T`; `fix` is the number as
/// it should be written. Checked on every token of a definition before it
/// is parsed ([`crate::parse`]).
pub fn literal_form(lit: &Lit) -> Option<syn::Error> {
    let (suffix, digits) = match lit {
        Lit::Int(i) => (i.suffix(), i.base10_digits()),
        Lit::Float(f) => (f.suffix(), f.base10_digits()),
        _ => return None,
    };
    let text = quote::ToTokens::to_token_stream(lit).to_string();
    let radix = ["0x", "0o", "0b"].iter().any(|p| text.starts_with(p));
    if suffix.is_empty() && !radix {
        return None;
    }
    let fix = if digits.contains(['.', 'e', 'E']) {
        digits.to_string()
    } else {
        format!("{digits}.0")
    };
    let what = if radix {
        "a number in another base than ten"
    } else {
        "a number with a type suffix"
    };
    Some(syn::Error::new(
        lit.span(),
        format!("`{text}` is {what}; numbers in a definition are plain decimals whose type is the mechanism's scalar (`f32` or `f64`): write `{fix}`"),
    ))
}

/// How names inside an expression resolve.
pub trait Scope {
    /// A constant's folded value.
    fn constant(&self, name: &Ident) -> Option<f64>;
    /// `true` for a run-time parameter.
    fn is_param(&self, name: &Ident) -> bool;
    /// `true` for a per-evaluation load value (only where loads may appear).
    fn is_load(&self, _name: &Ident) -> bool {
        false
    }
    /// An error for a name that is neither (with a suggestion).
    fn not_a_number(&self, name: &Ident) -> syn::Error;
}

/// Converts a user expression. Errors carry the span of the offending token.
pub fn convert(expr: &Expr, scope: &dyn Scope) -> Result<Value, syn::Error> {
    let span = expr.span();
    let kind = match expr {
        Expr::Lit(l) => match &l.lit {
            Lit::Float(f) => ValueKind::Lit(f.base10_parse::<f64>()?),
            Lit::Int(i) => ValueKind::Lit(i.base10_parse::<f64>()?),
            Lit::Str(_) => {
                return Err(syn::Error::new(
                    span,
                    "expected a number, not a string: remove the quotes",
                ))
            }
            _ => return Err(syn::Error::new(span, "expected a number")),
        },
        Expr::Path(p) => {
            let Some(name) = p.path.get_ident() else {
                return Err(syn::Error::new(
                    span,
                    "expected a number or a parameter name",
                ));
            };
            if let Some(x) = scope.constant(name) {
                ValueKind::Lit(x)
            } else if scope.is_param(name) {
                ValueKind::Param(name.clone())
            } else if scope.is_load(name) {
                ValueKind::Load(name.clone())
            } else {
                return Err(scope.not_a_number(name));
            }
        }
        Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => {
            ValueKind::Neg(Box::new(convert(&u.expr, scope)?))
        }
        Expr::Paren(p) => return convert(&p.expr, scope),
        Expr::Group(g) => return convert(&g.expr, scope),
        Expr::Binary(b) => {
            let op = match b.op {
                BinOp::Add(_) => '+',
                BinOp::Sub(_) => '-',
                BinOp::Mul(_) => '*',
                BinOp::Div(_) => '/',
                _ => {
                    return Err(syn::Error::new(
                        b.op.span(),
                        "only `+`, `-`, `*` and `/` are allowed in a dimension",
                    ))
                }
            };
            ValueKind::Bin(
                Box::new(convert(&b.left, scope)?),
                op,
                Box::new(convert(&b.right, scope)?),
            )
        }
        _ => {
            return Err(syn::Error::new_spanned(
                expr,
                "expected a number, a parameter, or arithmetic (`+ - * /`) on them",
            ))
        }
    };
    let value = Value {
        kind,
        span,
        tokens: quote::ToTokens::to_token_stream(expr),
    };
    check_finite(&value)?;
    Ok(value)
}
