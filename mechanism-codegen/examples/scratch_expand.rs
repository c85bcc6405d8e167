use quote::quote;
fn main() {
    let out = mechanism_codegen::expand(quote! {
        pub FourBarPoints {
            params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
            dof 1;
            let O2 = ground(0.0, 0.0);
            let O4 = ground(ground, 0.0);
            let A = crank(O2, crank, theta2) as link2;
            let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
            outputs { B }
        }
    });
    let file: syn::File = syn::parse2(out).unwrap();
    println!("{}", prettyplease::unparse(&file));
}
