#!/usr/bin/env python3
"""Write an OpenFOAM (interFoam, two-phase VOF) case of the charlesworth crater.

An independent Navier-Stokes reference for `wallload validate charlesworth`
(reference/charlesworth/README.md): the same 2D initial value problem as the
SPH case and its linear reference, solved by a finite-volume VOF code.

The crater comes from seed 001's formulae, computed here, not taken from
wallload: W = 32 lb of TNT, R0 = 9.6 W^0.3 ft (Van Dorn, seed 001 eq 4),
Hmax r = 35 W^0.54 ft^2 (mean of Whalin's 34 and Le Mehaute's 36, eqs 6-7),
eta0 R0 = 0.81 Hmax r (eq 5); the surface eta = eta0 (2 (x/R0)^2 - 1) for
|x - x_shot| <= R0 (seed 001 eq 1 on a section through the shot), still
water (eta = 0) beyond, the water at rest. Depth 16.5 ft. Flume: vertical
walls at x = 0 and x = 40 m, shot at 15 m, gauge at 32.22 m (56.5 ft from
the shot), as scenarios/charlesworth1945.yaml.

Usage: make_case.py --dx 0.1 --out DIR [--end 8] [--air 6]
Then in DIR: blockMesh && interFoam (or decomposePar and mpirun).
Writes alpha.water at every cell centre of the vertical lines through the
gauge (and x_shot + 5, 10 m) every 0.05 s (a `sets` function object);
gauge.py sums them into the surface elevation.
"""
import argparse
import math
import os

FT = 0.3048
W_LB = 32.0
DEPTH = 16.5 * FT
X_SHOT = 15.0
X_WALL = 40.0
X_GAUGE = X_SHOT + 56.5 * FT  # 32.2212 m
R0 = 9.6 * W_LB**0.3 * FT
HMAX_R = 35.0 * W_LB**0.54 * FT * FT
ETA0 = 0.81 * HMAX_R / R0


def eta(x):
    u = abs(x - X_SHOT) / R0
    return ETA0 * (2 * u * u - 1) if u <= 1 else 0.0


HEADER = """FoamFile
{{
    version     2.0;
    format      ascii;
    class       {cls};
    object      {obj};
}}
"""


def write(path, cls, obj, body):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(HEADER.format(cls=cls, obj=obj))
        f.write(body)


def alpha_cells(nx, ny, dx, dy, sub=16):
    """Water fraction of each cell (x fastest, as blockMesh orders a single
    block), the column's water height averaged over `sub` points in x."""
    out = []
    for j in range(ny):
        y0 = j * dy
        for i in range(nx):
            a = 0.0
            for k in range(sub):
                x = (i + (k + 0.5) / sub) * dx
                hh = DEPTH + eta(x)
                a += min(max((hh - y0) / dy, 0.0), 1.0)
            out.append(a / sub)
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--dx", type=float, required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--end", type=float, default=8.0)
    ap.add_argument("--air", type=float, default=6.0, help="height of air above still water [m]")
    ap.add_argument("--procs", type=int, default=1)
    a = ap.parse_args()
    nx = int(round(X_WALL / a.dx))
    dx = X_WALL / nx
    top = DEPTH + a.air
    ny = int(round(top / a.dx))
    dy = top / ny
    d = a.out
    write(f"{d}/system/blockMeshDict", "dictionary", "blockMeshDict", f"""
convertToMeters 1;
vertices
(
    (0 0 0) ({X_WALL} 0 0) ({X_WALL} {top} 0) (0 {top} 0)
    (0 0 {dx}) ({X_WALL} 0 {dx}) ({X_WALL} {top} {dx}) (0 {top} {dx})
);
blocks ( hex (0 1 2 3 4 5 6 7) ({nx} {ny} 1) simpleGrading (1 1 1) );
edges ();
boundary
(
    walls {{ type wall; faces ( (0 4 7 3) (1 2 6 5) (0 1 5 4) ); }}
    atmosphere {{ type patch; faces ( (3 7 6 2) ); }}
    frontAndBack {{ type empty; faces ( (0 3 2 1) (4 5 6 7) ); }}
);
mergePatchPairs ();
""")
    lines = "\n".join(
        f"""    {name}
    {{
        type sets; libs ("libsampling.so"); writeControl adjustableRunTime; writeInterval 0.05;
        interpolationScheme cell; setFormat raw; fields (alpha.water);
        sets ( line {{ type uniform; axis y; start ({x:.4f} {dy / 2} {dx / 2}); end ({x:.4f} {top - dy / 2} {dx / 2}); nPoints {ny}; }} );
    }}"""
        for name, x in (("gauge", X_GAUGE), ("at20", X_SHOT + 5.0), ("at25", X_SHOT + 10.0)))
    write(f"{d}/system/controlDict", "dictionary", "controlDict", f"""
application interFoam;
startFrom startTime; startTime 0; stopAt endTime; endTime {a.end};
deltaT 1e-4; writeControl adjustableRunTime; writeInterval 1; purgeWrite 0;
writeFormat binary; writePrecision 8; writeCompression off; timeFormat general; timePrecision 6;
runTimeModifiable no; adjustTimeStep yes; maxCo 0.25; maxAlphaCo 0.25; maxDeltaT 0.01;
functions
{{
{lines}
}}
""")
    write(f"{d}/system/fvSchemes", "dictionary", "fvSchemes", """
ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes
{
    div(rhoPhi,U) Gauss linearUpwind grad(U);
    div(phi,alpha) Gauss vanLeer;
    div(phirb,alpha) Gauss linear;
    div(((rho*nuEff)*dev2(T(grad(U))))) Gauss linear;
}
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
""")
    write(f"{d}/system/fvSolution", "dictionary", "fvSolution", """
solvers
{
    "alpha.water.*" { nAlphaCorr 2; nAlphaSubCycles 1; cAlpha 1; MULESCorr yes; nLimiterIter 3;
                      solver smoothSolver; smoother symGaussSeidel; tolerance 1e-8; relTol 0; }
    "pcorr.*" { solver PCG; preconditioner DIC; tolerance 1e-5; relTol 0; }
    p_rgh { solver GAMG; smoother DIC; tolerance 1e-7; relTol 0.01; }
    p_rghFinal { $p_rgh; relTol 0; }
    "(U|UFinal)" { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-6; relTol 0; }
}
PIMPLE { momentumPredictor no; nOuterCorrectors 1; nCorrectors 3; nNonOrthogonalCorrectors 0; }
relaxationFactors { equations { ".*" 1; } }
""")
    write(f"{d}/system/decomposeParDict", "dictionary", "decomposeParDict", f"""
numberOfSubdomains {a.procs};
method simple;
coeffs {{ n ({a.procs} 1 1); }}
""")
    write(f"{d}/constant/transportProperties", "dictionary", "transportProperties", """
phases (water air);
water { transportModel Newtonian; nu 1e-06; rho 1000; }
air { transportModel Newtonian; nu 1.48e-05; rho 1; }
sigma 0.07;
""")
    write(f"{d}/constant/turbulenceProperties", "dictionary", "turbulenceProperties",
          "\nsimulationType laminar;\n")
    write(f"{d}/constant/g", "uniformDimensionedVectorField", "g",
          "\ndimensions [0 1 -2 0 0 0 0];\nvalue (0 -9.81 0);\n")
    walls = "walls { type slip; }"
    write(f"{d}/0/U", "volVectorField", "U", f"""
dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{{
    {walls}
    atmosphere {{ type pressureInletOutletVelocity; value uniform (0 0 0); }}
    frontAndBack {{ type empty; }}
}}
""")
    write(f"{d}/0/p_rgh", "volScalarField", "p_rgh", """
dimensions [1 -1 -2 0 0 0 0];
internalField uniform 0;
boundaryField
{
    walls { type fixedFluxPressure; value uniform 0; }
    atmosphere { type totalPressure; p0 uniform 0; }
    frontAndBack { type empty; }
}
""")
    al = alpha_cells(nx, ny, dx, dy)
    body = "\n".join(f"{v:.8g}" for v in al)
    write(f"{d}/0/alpha.water", "volScalarField", "alpha.water", f"""
dimensions [0 0 0 0 0 0 0];
internalField nonuniform List<scalar>
{len(al)}
(
{body}
)
;
boundaryField
{{
    walls {{ type zeroGradient; }}
    atmosphere {{ type inletOutlet; inletValue uniform 0; value uniform 0; }}
    frontAndBack {{ type empty; }}
}}
""")
    print(f"case {d}: {nx} x {ny} cells of {dx:.4f} x {dy:.4f} m; depth {DEPTH:.4f} m, "
          f"R0 {R0:.4f} m, eta0 {ETA0:.4f} m, gauge at {X_GAUGE:.4f} m")


if __name__ == "__main__":
    main()
