// The gas momentum equation's stress term (UEqn.H),
//     div(mu*voidfraction*dev2(T(grad(U)))),
// on a 3-D hexahedral mesh, each step of it written as the solver writes it.
// Each operation there may take its argument's temporary for its result, and
// OpenFOAM's field loops declare result and argument __restrict__: a result
// component that reads other components of the same element (a transpose, a
// trace) can then be formed from components already overwritten, the way
// v1912's reconstruct got z wrong (FluxVelocity.H). A linear velocity with a
// full, non-symmetric gradient sees every such mix-up:
//     U = A.x              grad(U) = A^T (OpenFOAM's (grad U)_ij = d_i U_j)
//     T(grad(U)) = A       dev2(A) = A - 2/3 tr(A) I
//     eps = e0 + g.x       div(mu eps dev2(A)) = mu g.dev2(A)
// Gauss linear is exact for linear fields on this rectilinear graded mesh
// (every face centre on the line between its cells' centres, the boundary
// values the fields' own), so each result must match to round-off.
#include "fvCFD.H"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

namespace
{

namespace fs = std::filesystem;

// a box graded in all three directions, off the origin; odd numbers of
// cells and of faces on each side, so that the loops' unrolled bodies and
// their single-element ends both run
constexpr int nx = 5, ny = 3, nz = 7;
const Foam::point origin(0.01, -0.02, 0.03);
const Foam::vector extent(0.05, 0.04, 0.09);

// full, non-symmetric, no two entries alike (1/s); tr A = 2.3
const Foam::tensor A
(
     1.0, -2.0,  3.5,
     0.7, -1.3,  2.2,
    -4.1,  0.9,  2.6
);
constexpr double e0 = 0.4;                    // void fraction at the origin
const Foam::vector g(2.0, -3.0, 4.0);        // its gradient (1/m)
constexpr double muValue = 1.8e-5;            // Pa s

void writeCase(const fs::path& dir)
{
    fs::create_directories(dir/"system");
    fs::create_directories(dir/"constant");
    const auto header = [](std::ofstream& os, const char* object)
    {
        os << "FoamFile { version 2.0; format ascii; class dictionary; object "
           << object << "; }\n";
    };
    std::ofstream cd(dir/"system"/"controlDict");
    header(cd, "controlDict");
    cd << "application none; startFrom startTime; startTime 0; stopAt endTime;"
          " endTime 1; deltaT 1; writeControl timeStep; writeInterval 1;\n";
    // the cases' schemes for these terms
    std::ofstream fs(dir/"system"/"fvSchemes");
    header(fs, "fvSchemes");
    fs << "ddtSchemes { default Euler; } gradSchemes { default Gauss linear; }"
          " divSchemes { default none;"
          " div(((mu*voidfraction)*dev2(T(grad(U))))) Gauss linear; }"
          " laplacianSchemes { default Gauss linear corrected; }"
          " interpolationSchemes { default linear; } snGradSchemes { default corrected; }\n";
    std::ofstream fv(dir/"system"/"fvSolution");
    header(fv, "fvSolution");
    fv << "solvers { }\n";
    std::ofstream bm(dir/"system"/"blockMeshDict");
    header(bm, "blockMeshDict");
    const Foam::point o = origin, e = origin + extent;
    bm << "scale 1;\nvertices (\n"
       << '(' << o.x() << ' ' << o.y() << ' ' << o.z() << ") "
       << '(' << e.x() << ' ' << o.y() << ' ' << o.z() << ") "
       << '(' << e.x() << ' ' << e.y() << ' ' << o.z() << ") "
       << '(' << o.x() << ' ' << e.y() << ' ' << o.z() << ")\n"
       << '(' << o.x() << ' ' << o.y() << ' ' << e.z() << ") "
       << '(' << e.x() << ' ' << o.y() << ' ' << e.z() << ") "
       << '(' << e.x() << ' ' << e.y() << ' ' << e.z() << ") "
       << '(' << o.x() << ' ' << e.y() << ' ' << e.z() << ")\n);\n"
       << "blocks ( hex (0 1 2 3 4 5 6 7) (" << nx << ' ' << ny << ' ' << nz
       << ") simpleGrading (2 0.5 3) );\n"
       << "boundary ( bottom { type wall; faces ((0 3 2 1)); }"
          " top { type wall; faces ((4 5 6 7)); }"
          " front { type wall; faces ((0 1 5 4)); }"
          " back { type wall; faces ((2 3 7 6)); }"
          " left { type wall; faces ((3 0 4 7)); }"
          " right { type wall; faces ((1 2 6 5)); } );\n";
}


//- The largest |computed - expected| over the cells and the boundary faces
//  of a field whose expected value is the same everywhere, with the place
//  and both values of the worst one
template<class Type>
struct Deviation
{
    double max = 0;
    std::string where;
    Type computed = Foam::Zero;
};

template<class Type>
void take
(
    Deviation<Type>& d,
    const Type& computed,
    const Type& expected,
    const std::string& where
)
{
    const double m = Foam::mag(computed - expected);
    if (m > d.max || d.where.empty())
    {
        d.max = m;
        d.where = where;
        d.computed = computed;
    }
}

template<class Type>
Deviation<Type> deviation
(
    const Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh>& f,
    const Type& expected,
    bool boundaries
)
{
    Deviation<Type> d;
    forAll(f, celli)
    {
        take(d, f[celli], expected, "cell " + std::to_string(celli));
    }
    if (!boundaries) return d;
    forAll(f.boundaryField(), patchi)
    {
        const auto& pf = f.boundaryField()[patchi];
        forAll(pf, facei)
        {
            take
            (
                d, pf[facei], expected,
                "patch " + pf.patch().name() + " face " + std::to_string(facei)
            );
        }
    }
    return d;
}

template<class Type>
std::string describe(const Deviation<Type>& d, const Type& expected)
{
    std::ostringstream os;
    os.precision(12);
    os << "worst at " << d.where << ": computed (";
    for (Foam::direction c = 0; c < Type::nComponents; ++c)
    {
        os << (c ? " " : "") << Foam::component(d.computed, c);
    }
    os << "), expected (";
    for (Foam::direction c = 0; c < Type::nComponents; ++c)
    {
        os << (c ? " " : "") << Foam::component(expected, c);
    }
    os << "), |difference| " << d.max;
    return os.str();
}


class StressTerm : public ::testing::Test
{
protected:
    static void SetUpTestSuite()
    {
        dir_ = fs::absolute("stressTermCase");
        fs::remove_all(dir_);
        writeCase(dir_);
        const std::string cmd =
            "cd '" + dir_.string() + "' && blockMesh > log.blockMesh 2>&1";
        ASSERT_EQ(std::system(cmd.c_str()), 0) << "blockMesh failed in " << dir_;
        time_.reset
        (
            new Foam::Time
            (
                Foam::Time::controlDictName,
                Foam::fileName(dir_.parent_path().string()),
                Foam::fileName(dir_.filename().string())
            )
        );
        mesh_.reset
        (
            new Foam::fvMesh
            (
                Foam::IOobject
                (
                    Foam::fvMesh::defaultRegion, time_->timeName(), *time_,
                    Foam::IOobject::MUST_READ
                )
            )
        );
        U_.reset(linearVelocity(*mesh_));
        voidfraction_.reset(linearVoidFraction(*mesh_));
    }

    static void TearDownTestSuite()
    {
        voidfraction_.reset();
        U_.reset();
        mesh_.reset();
        time_.reset();
    }

    // U = A.x in the cells and on the (fixedValue) boundary faces
    static Foam::volVectorField* linearVelocity(const Foam::fvMesh& mesh)
    {
        auto* U = new Foam::volVectorField
        (
            Foam::IOobject("U", mesh.time().timeName(), mesh),
            mesh,
            Foam::dimensionedVector("U", Foam::dimVelocity, Foam::Zero),
            Foam::fixedValueFvPatchVectorField::typeName
        );
        U->primitiveFieldRef() = A & mesh.C().primitiveField();
        forAll(U->boundaryField(), patchi)
        {
            U->boundaryFieldRef()[patchi] == (A & mesh.C().boundaryField()[patchi]);
        }
        return U;
    }

    // eps = e0 + g.x likewise (between 0.4 and 0.87 over the box)
    static Foam::volScalarField* linearVoidFraction(const Foam::fvMesh& mesh)
    {
        auto* eps = new Foam::volScalarField
        (
            Foam::IOobject("voidfraction", mesh.time().timeName(), mesh),
            mesh,
            Foam::dimensionedScalar("voidfraction", Foam::dimless, e0)
        );
        eps->primitiveFieldRef() = e0 + (g & (mesh.C().primitiveField() - origin));
        forAll(eps->boundaryField(), patchi)
        {
            eps->boundaryFieldRef()[patchi] ==
                e0 + (g & (mesh.C().boundaryField()[patchi] - origin));
        }
        return eps;
    }

    static fs::path dir_;
    static std::unique_ptr<Foam::Time> time_;
    static std::unique_ptr<Foam::fvMesh> mesh_;
    static std::unique_ptr<Foam::volVectorField> U_;
    static std::unique_ptr<Foam::volScalarField> voidfraction_;
};

fs::path StressTerm::dir_;
std::unique_ptr<Foam::Time> StressTerm::time_;
std::unique_ptr<Foam::fvMesh> StressTerm::mesh_;
std::unique_ptr<Foam::volVectorField> StressTerm::U_;
std::unique_ptr<Foam::volScalarField> StressTerm::voidfraction_;

const Foam::tensor dev2A = A - (2.0/3.0)*Foam::tr(A)*Foam::I;

// round-off of sums over a cell's faces, relative to the terms' size
constexpr double tolerance = 1e-10;

//- Check one field against its expected value, and say in the log how far
//  it is off at its worst
template<class Type>
void expectNear
(
    const char* what,
    const Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh>& f,
    const Type& expected,
    double scale,
    bool boundaries
)
{
    const auto d = deviation(f, expected, boundaries);
    std::cout << what << ": " << describe(d, expected) << '\n';
    EXPECT_LT(d.max, tolerance*scale) << what;
}

} // namespace


// Each field below is formed from temporaries exactly as UEqn.H forms it
// (nothing stored in a named field in between), so that each operation gets
// the chance to write into its argument.

TEST_F(StressTerm, GradientOfTheLinearVelocityIsATransposed)
{
    const Foam::volVectorField& U = *U_;
    expectNear("grad(U)", Foam::fvc::grad(U)(), A.T(), Foam::mag(A), true);
}


TEST_F(StressTerm, TransposeOfTheGradientTemporaryIsA)
{
    const Foam::volVectorField& U = *U_;
    expectNear("T(grad(U))", T(Foam::fvc::grad(U))(), A, Foam::mag(A), true);
}


TEST_F(StressTerm, Dev2OfTheTransposeTemporaryIsDev2A)
{
    const Foam::volVectorField& U = *U_;
    expectNear
    (
        "dev2(T(grad(U)))", dev2(T(Foam::fvc::grad(U)))(), dev2A,
        Foam::mag(A), true
    );
}


TEST_F(StressTerm, StressDivergenceIsMuGDotDev2A)
{
    const Foam::volVectorField& U = *U_;
    const Foam::volScalarField& voidfraction = *voidfraction_;
    const Foam::dimensionedScalar mu("mu", Foam::dimDynamicViscosity, muValue);
    // the cells on the walls too; fvc::div's boundary values take no part
    // in the equation
    expectNear
    (
        "div(mu*voidfraction*dev2(T(grad(U))))",
        Foam::fvc::div(mu*voidfraction*dev2(T(Foam::fvc::grad(U))))(),
        muValue*(g & dev2A), muValue*Foam::mag(g)*Foam::mag(dev2A), false
    );
}


// What the checks above are about: in v1912 each of T, dev2 and the product
// with mu*voidfraction writes its result into its tensor argument's storage
// when that is a temporary. Should OpenFOAM stop doing so, they pass
// whatever its loops do, and this says so.
TEST_F(StressTerm, EachStepWritesIntoItsArgumentsStorage)
{
    const Foam::volVectorField& U = *U_;
    const Foam::volScalarField& voidfraction = *voidfraction_;
    const Foam::dimensionedScalar mu("mu", Foam::dimDynamicViscosity, muValue);
    const auto storage = [](const Foam::tmp<Foam::volTensorField>& t)
    {
        return static_cast<const void*>(t().primitiveField().cdata());
    };
    const Foam::tmp<Foam::volTensorField> gradU(Foam::fvc::grad(U));
    const void* const cells = storage(gradU);
    const Foam::tmp<Foam::volTensorField> TgradU(T(gradU));
    EXPECT_EQ(storage(TgradU), cells) << "T";
    const Foam::tmp<Foam::volTensorField> S(dev2(TgradU));
    EXPECT_EQ(storage(S), cells) << "dev2";
    const Foam::tmp<Foam::volTensorField> stress(mu*voidfraction*S);
    EXPECT_EQ(storage(stress), cells) << "mu*voidfraction*";
}


// ************************************************************************* //
