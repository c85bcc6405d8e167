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
    /// `f(x)` or `f(x, y)`: one of the [`Func`]s (its arguments in order).
    Call(Func, Vec<Value>),
}

/// The functions a dimension may use (radians for the angles; `pi` is a
/// constant beside them). Folded at expansion time on numbers; on
/// parameters computed by the core's kernels (`mechanism::Real`), so
/// `f32` stays `f32`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Func {
    /// `sqrt(x)`, `x >= 0`.
    Sqrt,
    /// `sin(x)`, `x` in radians.
    Sin,
    /// `cos(x)`, `x` in radians.
    Cos,
    /// `tan(x)`, `x` in radians.
    Tan,
    /// `atan2(y, x)`: the angle of `(x, y)` in radians, in `[-pi, pi]`.
    Atan2,
    /// `hypot(x, y)`: `sqrt(x^2 + y^2)`.
    Hypot,
    /// `abs(x)`.
    Abs,
    /// `min(x, y)`.
    Min,
    /// `max(x, y)`.
    Max,
}

impl Func {
    /// Every function, with the name a definition writes.
    pub const ALL: [(&'static str, Func); 9] = [
        ("sqrt", Func::Sqrt),
        ("sin", Func::Sin),
        ("cos", Func::Cos),
        ("tan", Func::Tan),
        ("atan2", Func::Atan2),
        ("hypot", Func::Hypot),
        ("abs", Func::Abs),
        ("min", Func::Min),
        ("max", Func::Max),
    ];

    /// The function written `name`.
    pub fn named(name: &str) -> Option<Func> {
        Func::ALL.iter().find(|(n, _)| *n == name).map(|(_, f)| *f)
    }

    /// The name a definition writes.
    pub fn name(self) -> &'static str {
        Func::ALL
            .iter()
            .find(|(_, f)| *f == self)
            .map_or("", |(n, _)| n)
    }

    /// How many arguments it takes.
    pub fn arity(self) -> usize {
        match self {
            Func::Atan2 | Func::Hypot | Func::Min | Func::Max => 2,
            _ => 1,
        }
    }

    /// Its value in `f64` (`std`'s functions, correctly rounded or within
    /// an ulp: the expansion-time fold).
    fn apply(self, a: &[f64]) -> f64 {
        match self {
            Func::Sqrt => a[0].sqrt(),
            Func::Sin => a[0].sin(),
            Func::Cos => a[0].cos(),
            Func::Tan => a[0].tan(),
            Func::Atan2 => a[0].atan2(a[1]),
            Func::Hypot => a[0].hypot(a[1]),
            Func::Abs => a[0].abs(),
            Func::Min => a[0].min(a[1]),
            Func::Max => a[0].max(a[1]),
        }
    }

    /// Rust code in the scalar type `T` for its arguments `a`.
    fn emit(self, a: &[TokenStream]) -> TokenStream {
        let real = quote!(<T as ::mechanism::Real>);
        match self {
            Func::Sqrt => quote!(#real::sqrt_kernel(#(#a)*)),
            Func::Sin => quote!(#real::sin_cos_kernel(#(#a)*).0),
            Func::Cos => quote!(#real::sin_cos_kernel(#(#a)*).1),
            Func::Tan => quote!({
                let (s, c) = #real::sin_cos_kernel(#(#a)*);
                s / c
            }),
            Func::Atan2 => {
                let (y, x) = (&a[0], &a[1]);
                quote!(#real::atan2_kernel(#y, #x))
            }
            Func::Hypot => {
                let (x, y) = (&a[0], &a[1]);
                quote!(::mechanism::geometry::length(&::mechanism::Vector2::new(#x, #y)))
            }
            Func::Abs => quote!(::mechanism::geometry::abs(#(#a)*)),
            Func::Min => {
                let (x, y) = (&a[0], &a[1]);
                quote!(::mechanism::geometry::min(#x, #y))
            }
            Func::Max => {
                let (x, y) = (&a[0], &a[1]);
                quote!(::mechanism::geometry::max(#x, #y))
            }
        }
    }
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
        self.eval_with(&|_| None)
    }

    /// The number with each parameter valued by `param` (`None`: unknown,
    /// and so is the result); a load is unknown.
    pub fn eval_with(&self, param: &dyn Fn(&Ident) -> Option<f64>) -> Option<f64> {
        match &self.kind {
            ValueKind::Lit(x) => Some(*x),
            ValueKind::Param(p) => param(p),
            ValueKind::Load(_) => None,
            ValueKind::Neg(v) => v.eval_with(param).map(|x| -x),
            ValueKind::Bin(a, op, b) => {
                let (a, b) = (a.eval_with(param)?, b.eval_with(param)?);
                Some(match op {
                    '+' => a + b,
                    '-' => a - b,
                    '*' => a * b,
                    _ => a / b,
                })
            }
            ValueKind::Call(f, args) => {
                let mut xs = [0.0; 2];
                for (x, a) in xs.iter_mut().zip(args) {
                    *x = a.eval_with(param)?;
                }
                Some(f.apply(&xs))
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
            ValueKind::Call(f, args) => {
                let args: Vec<TokenStream> = args.iter().map(Value::emit).collect();
                f.emit(&args)
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
        (ValueKind::Call(Func::Sqrt, a), _) if a[0].fold().is_some_and(|x| x < 0.0) => format!(
            "`{}` is the square root of a negative number ({}); a dimension must be a real number: check the sign of the expression inside",
            v.tokens,
            a[0].fold().unwrap_or_default()
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
            } else if name == "pi" {
                ValueKind::Lit(core::f64::consts::PI)
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
        Expr::Call(call) => call_kind(call, scope)?,
        _ => {
            return Err(syn::Error::new_spanned(
                expr,
                "expected a number, a parameter, arithmetic (`+ - * /`) or a function (`sqrt`, `sin`, `cos`, `tan`, `atan2`, `hypot`, `abs`, `min`, `max`) on them",
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

/// `f(args)` with `f` one of [`Func::ALL`] and as many arguments as it takes.
/// Errors on the function's name (unknown, with the nearest one) or on the
/// call (the wrong number of arguments).
fn call_kind(call: &syn::ExprCall, scope: &dyn Scope) -> Result<ValueKind, syn::Error> {
    let name = match &*call.func {
        Expr::Path(p) => p.path.get_ident(),
        _ => None,
    };
    let Some(name) = name else {
        return Err(syn::Error::new_spanned(
            &call.func,
            "expected a function name (`sqrt`, `sin`, `cos`, `tan`, `atan2`, `hypot`, `abs`, `min`, `max`)",
        ));
    };
    let Some(func) = Func::named(&name.to_string()) else {
        let names: Vec<&str> = Func::ALL.iter().map(|(n, _)| *n).collect();
        let hint = match crate::diag::nearest(&name.to_string(), names.iter().copied()) {
            Some(near) => format!("did you mean `{near}`?"),
            None => format!("the functions are `{}`", names.join("`, `")),
        };
        return Err(syn::Error::new(
            name.span(),
            format!("`{name}` is not a function a dimension may use; {hint}"),
        ));
    };
    if call.args.len() != func.arity() {
        let (n, s) = (func.arity(), if func.arity() == 1 { "" } else { "s" });
        return Err(syn::Error::new_spanned(
            call,
            format!(
                "`{}` takes {n} argument{s}, not {}: write `{}({})`",
                func.name(),
                call.args.len(),
                func.name(),
                if n == 1 { "x" } else { "x, y" }
            ),
        ));
    }
    let args = call
        .args
        .iter()
        .map(|a| convert(a, scope))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(ValueKind::Call(func, args))
}

#[cfg(test)]
mod tests {
    //! Functions in dimensions: folding on numbers, the code on parameters,
    //! and the errors on the user's tokens.
    use super::*;

    /// A scope with the parameter `r` and no constants.
    struct OneParam;

    impl Scope for OneParam {
        fn constant(&self, _: &Ident) -> Option<f64> {
            None
        }
        fn is_param(&self, name: &Ident) -> bool {
            name == "r"
        }
        fn not_a_number(&self, name: &Ident) -> syn::Error {
            syn::Error::new(name.span(), "not a number")
        }
    }

    fn value(src: &str) -> Result<Value, syn::Error> {
        convert(&syn::parse_str::<Expr>(src).unwrap(), &OneParam)
    }

    #[test]
    fn functions_of_numbers_fold_to_their_f64_values() {
        // Proves each function folds at expansion time to std's value (the
        // right-hand sides are written independently: exact squares,
        // textbook angles, Pythagorean triples), and `pi` is the constant.
        let fold = |s: &str| value(s).unwrap().fold().unwrap();
        assert_eq!(fold("sqrt(2.25)"), 1.5);
        assert_eq!(fold("hypot(3.0, 4.0)"), 5.0);
        assert_eq!(fold("abs(-2.5)"), 2.5);
        assert_eq!(fold("min(2.0, -1.0) + max(2.0, -1.0)"), 1.0);
        // Within 2 ulp: the argument `pi / k` is itself rounded.
        assert!((fold("sin(pi / 6.0)") - 0.5).abs() <= 2.0 * f64::EPSILON / 2.0);
        assert!((fold("cos(pi / 3.0)") - 0.5).abs() <= 2.0 * f64::EPSILON / 2.0);
        assert!((fold("tan(pi / 4.0)") - 1.0).abs() <= 2.0 * f64::EPSILON);
        assert_eq!(fold("atan2(1.0, 1.0) * 4.0"), core::f64::consts::PI);
        // A triangle's vertex from its three sides (3, 4, 5 on a base of 5).
        let x = fold("(4.0 * 4.0 + 5.0 * 5.0 - 3.0 * 3.0) / (2.0 * 5.0)");
        assert_eq!(x, 3.2);
        // 3.2^2 is rounded: within 2 ulp of 2.4.
        assert!((fold("sqrt(4.0 * 4.0 - 3.2 * 3.2)") - 2.4).abs() <= 4.0 * f64::EPSILON);
    }

    #[test]
    fn functions_of_parameters_emit_the_core_kernels() {
        // Proves a call on a parameter is not folded and emits the kernel of
        // the scalar type (no `f64` std call in `f32` code).
        let v = value("sqrt(r * r + 1.0)").unwrap();
        assert!(v.fold().is_none());
        let code = v.emit().to_string();
        assert!(code.contains("sqrt_kernel"), "{code}");
        let code = value("atan2(r, 2.0)").unwrap().emit().to_string();
        assert!(code.contains("atan2_kernel"), "{code}");
        assert_eq!(
            value("sqrt(r)").unwrap().eval_with(&|_| Some(6.25)),
            Some(2.5)
        );
    }

    #[test]
    fn bad_calls_are_errors_on_the_users_tokens() {
        // Proves an unknown function, the wrong number of arguments and a
        // square root of a negative number are errors that say what to write.
        let err = |s: &str| value(s).unwrap_err().to_string();
        assert!(err("sqr(2.0)").contains("did you mean `sqrt`"));
        assert!(err("atan2(1.0)").contains("`atan2` takes 2 arguments, not 1"));
        assert!(err("sin(1.0, 2.0)").contains("`sin` takes 1 argument, not 2"));
        assert!(err("sqrt(1.0 - 2.0)").contains("square root of a negative number (-1)"));
        assert!(err("f(1.0)").contains("the functions are"));
    }
}
