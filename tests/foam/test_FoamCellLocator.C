// Particle location and the divided void fraction on real OpenFOAM meshes:
// a slanted, graded block (non-orthogonal faces, cells of different sizes)
// whose cell for any point is known from the block's affine map.
#include "fvCFD.H"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>

#include "DividedVoidFraction.hpp"
#include "FoamCellLocator.H"
#include "Parameters.hpp"

namespace
{

namespace fs = std::filesystem;

// The block: unit cell (s,t,r) in [0,1]^3 maps to
//   x = Lx s + shear z,  y = Ly t,  z = Lz r
// with nx x ny x nz cells; x is graded (last/first cell width = 2).
constexpr double Lx = 0.06, Ly = 0.02, Lz = 0.09, shear = 0.3;
constexpr int nx = 4, ny = 2, nz = 6;
constexpr double grading = 2.0;

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
    // an fvMesh reads its schemes and solution dictionaries, even unused
    std::ofstream fs(dir/"system"/"fvSchemes");
    header(fs, "fvSchemes");
    fs << "ddtSchemes { default Euler; } gradSchemes { default Gauss linear; }"
          " divSchemes { default none; } laplacianSchemes { default none; }"
          " interpolationSchemes { default linear; } snGradSchemes { default corrected; }\n";
    std::ofstream fv(dir/"system"/"fvSolution");
    header(fv, "fvSolution");
    fv << "solvers { }\n";
    std::ofstream bm(dir/"system"/"blockMeshDict");
    header(bm, "blockMeshDict");
    const double X = Lx, Y = Ly, Z = Lz, S = shear*Lz;
    bm << "scale 1;\nvertices (\n"
       << "(0 0 0) (" << X << " 0 0) (" << X << ' ' << Y << " 0) (0 " << Y << " 0)\n"
       << '(' << S << " 0 " << Z << ") (" << X + S << " 0 " << Z << ") ("
       << X + S << ' ' << Y << ' ' << Z << ") (" << S << ' ' << Y << ' ' << Z << ")\n);\n"
       << "blocks ( hex (0 1 2 3 4 5 6 7) (" << nx << ' ' << ny << ' ' << nz
       << ") simpleGrading (" << grading << " 1 1) );\n"
       << "boundary ( walls { type wall; faces ((0 3 2 1) (4 5 6 7) (0 1 5 4)"
          " (1 2 6 5) (2 3 7 6) (3 0 4 7)); } );\n";
}

// Cell face positions of the graded direction in s in [0,1]: geometric
// widths with ratio grading^(1/(n-1)).
std::vector<double> gradedFaces()
{
    const double q = std::pow(grading, 1.0/(nx - 1));
    std::vector<double> faces{0};
    double w = 1, sum = 0;
    for (int i = 0; i < nx; ++i) { sum += w; w *= q; }
    w = 1/sum;
    for (int i = 0; i < nx; ++i) { faces.push_back(faces.back() + w); w *= q; }
    return faces;
}

spoutlab::Vec3 toPoint(double s, double t, double r)
{
    return {Lx*s + shear*Lz*r, Ly*t, Lz*r};
}

// Run blockMesh in the case and read its mesh.
void meshCase
(
    const fs::path& dir,
    std::unique_ptr<Foam::Time>& time,
    std::unique_ptr<Foam::fvMesh>& mesh
)
{
    const std::string cmd = "cd '" + dir.string() + "' && blockMesh > log.blockMesh 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << "blockMesh failed in " << dir;
    time.reset
    (
        new Foam::Time
        (
            Foam::Time::controlDictName,
            Foam::fileName(dir.parent_path().string()),
            Foam::fileName(dir.filename().string())
        )
    );
    mesh.reset
    (
        new Foam::fvMesh
        (
            Foam::IOobject
            (
                Foam::fvMesh::defaultRegion, time->timeName(), *time,
                Foam::IOobject::MUST_READ
            )
        )
    );
}

class FoamMesh : public ::testing::Test
{
protected:
    static void SetUpTestSuite()
    {
        dir_ = fs::absolute("locatorCase");
        fs::remove_all(dir_);
        writeCase(dir_);
        meshCase(dir_, time_, mesh_);
    }

    static void TearDownTestSuite()
    {
        mesh_.reset();
        time_.reset();
    }

    // The cell that contains unit-cube point (s, t, r) (none on a face).
    static spoutlab::label expectedCell(double s, double t, double r)
    {
        const auto faces = gradedFaces();
        int i = 0;
        while (i + 1 < nx && s >= faces[i + 1]) ++i;
        const int j = std::min(int(t*ny), ny - 1);
        const int k = std::min(int(r*nz), nz - 1);
        return i + nx*(j + ny*k);   // blockMesh numbering
    }

    static fs::path dir_;
    static std::unique_ptr<Foam::Time> time_;
    static std::unique_ptr<Foam::fvMesh> mesh_;
};

fs::path FoamMesh::dir_;
std::unique_ptr<Foam::Time> FoamMesh::time_;
std::unique_ptr<Foam::fvMesh> FoamMesh::mesh_;


TEST_F(FoamMesh, FindsTheCellOfRandomPointsWithAndWithoutHint)
{
    spoutlab::FoamCellLocator locator(*mesh_);
    ASSERT_EQ(locator.nCells(), nx*ny*nz);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.001, 0.999);
    for (int n = 0; n < 2000; ++n)
    {
        const double s = u(rng), t = u(rng), r = u(rng);
        const auto expected = expectedCell(s, t, r);
        const auto p = toPoint(s, t, r);
        EXPECT_EQ(locator.findCell(p, -1), expected);
        EXPECT_EQ(locator.findCell(p, 0), expected);          // far hint
        EXPECT_EQ(locator.findCell(p, expected), expected);   // exact hint
    }
}


TEST_F(FoamMesh, SlantedCellsAreNotALattice)
{
    // this mesh's cells are searched by the walk, not looked up
    EXPECT_FALSE(spoutlab::FoamCellLocator(*mesh_).onLattice());
}


TEST_F(FoamMesh, PointsOnFacesBelongToAnAdjacentCell)
{
    spoutlab::FoamCellLocator locator(*mesh_);
    const auto faces = gradedFaces();
    // on an interior x-face (slanted), an interior z-face, and an edge
    const std::vector<std::array<double, 3>> onFaces =
        {{faces[2], 0.3, 0.4}, {0.37, 0.3, 0.5}, {faces[1], 0.5, 2.0/nz}};
    for (const auto& q : onFaces)
    {
        const auto p = toPoint(q[0], q[1], q[2]);
        const auto cell = locator.findCell(p, -1);
        ASSERT_GE(cell, 0);
        // it must be one of the cells touching the point
        const double e = 1e-7;
        bool adjacent = false;
        for (double ds : {-e, e}) for (double dt : {-e, e}) for (double dr : {-e, e})
        {
            adjacent = adjacent
                || cell == expectedCell(q[0] + ds, q[1] + dt, q[2] + dr);
        }
        EXPECT_TRUE(adjacent) << "cell " << cell;
        EXPECT_EQ(locator.findCell(p, cell), cell);  // stable under its own hint
    }
    // on the outer boundary: inside the mesh
    EXPECT_GE(locator.findCell(toPoint(0.0, 0.5, 0.5), -1), 0);
    EXPECT_GE(locator.findCell(toPoint(0.5, 1.0, 0.5), -1), 0);
    EXPECT_GE(locator.findCell(toPoint(0.5, 0.5, 0.0), -1), 0);
}


TEST_F(FoamMesh, PointsOutsideTheMeshAreNotFound)
{
    spoutlab::FoamCellLocator locator(*mesh_);
    const double e = 1e-6;
    EXPECT_EQ(locator.findCell(toPoint(-e, 0.5, 0.5), -1), -1);
    EXPECT_EQ(locator.findCell(toPoint(1 + e, 0.5, 0.5), -1), -1);
    EXPECT_EQ(locator.findCell(toPoint(0.5, -e, 0.5), -1), -1);
    EXPECT_EQ(locator.findCell(toPoint(0.5, 0.5, 1 + e), -1), -1);
    // just outside the slanted wall, with the neighbouring cell as hint
    const auto inside = expectedCell(0.01, 0.5, 0.5);
    EXPECT_EQ(locator.findCell(toPoint(-e, 0.5, 0.5), inside), -1);
}


TEST_F(FoamMesh, SphereInsideCellUsesTheSlantedFacePlanes)
{
    spoutlab::FoamCellLocator locator(*mesh_);
    const auto cell = expectedCell(0.5, 0.25, 0.5);
    const Foam::point c = mesh_->C()[cell];
    const spoutlab::Vec3 centre{c.x(), c.y(), c.z()};
    // the smallest distance from the centre to a face plane of this cell
    double dMin = 1e300;
    for (const Foam::label f : mesh_->cells()[cell])
    {
        const Foam::vector n = mesh_->faceAreas()[f]/Foam::mag(mesh_->faceAreas()[f]);
        dMin = std::min(dMin, std::abs((mesh_->faceCentres()[f] - c) & n));
    }
    EXPECT_TRUE(locator.sphereInsideCell(cell, centre, 0.99*dMin));
    EXPECT_FALSE(locator.sphereInsideCell(cell, centre, 1.01*dMin));
}


TEST_F(FoamMesh, DividedVoidFractionConservesSolidVolume)
{
    spoutlab::FoamCellLocator locator(*mesh_);
    auto model = spoutlab::VoidFractionModel::New
    (
        "divided", spoutlab::Parameters("test")
    );
    // particles everywhere, many cut by faces, some by the walls
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<spoutlab::Particle> particles;
    double total = 0;
    for (int n = 0; n < 500; ++n)
    {
        spoutlab::Particle p;
        p.id = n + 1;
        p.x = toPoint(u(rng), u(rng), u(rng));
        p.radius = 0.002 + 0.003*u(rng);
        total += p.volume();
        particles.push_back(p);
    }
    const auto result = model->compute(locator, particles);
    ASSERT_TRUE(result.lostParticles.empty());
    double sum = 0;
    for (double v : result.solidVolume) sum += v;
    EXPECT_NEAR(sum/total, 1.0, 1e-12);

    // a particle cut by the slanted x = 0 wall still counts fully
    spoutlab::Particle wall;
    wall.id = 1;
    wall.x = toPoint(0.02, 0.5, 0.5);
    wall.radius = 0.004;
    const auto one = model->compute(locator, {wall});
    double s1 = 0;
    for (double v : one.solidVolume) s1 += v;
    EXPECT_NEAR(s1/wall.volume(), 1.0, 1e-12);
}


// An L-shaped domain (two blocks; the square x, z in [1, 2] is missing),
// like the gas mesh around the draft plates and the base's staircase:
// points in the missing square belong to no cell, whatever the hint.
class LShapedMesh : public ::testing::Test
{
protected:
    static void SetUpTestSuite()
    {
        dir_ = fs::absolute("lShapedCase");
        fs::remove_all(dir_);
        writeCase(dir_);                  // dictionaries; blockMeshDict replaced
        std::ofstream bm(dir_/"system"/"blockMeshDict");
        bm << "FoamFile { version 2.0; format ascii; class dictionary;"
              " object blockMeshDict; }\nscale 1;\nvertices (\n"
              "(0 0 0) (1 0 0) (2 0 0) (0 1 0) (1 1 0) (2 1 0)\n"
              "(0 0 1) (1 0 1) (2 0 1) (0 1 1) (1 1 1) (2 1 1)\n"
              "(0 0 2) (1 0 2) (0 1 2) (1 1 2)\n);\n"
              "blocks ( hex (0 1 4 3 6 7 10 9) (4 1 4) simpleGrading (1 1 1)\n"
              "         hex (1 2 5 4 7 8 11 10) (4 1 4) simpleGrading (1 1 1)\n"
              "         hex (6 7 10 9 12 13 15 14) (4 1 4) simpleGrading (1 1 1) );\n"
              "defaultPatch { name walls; type wall; }\nboundary ( );\n";
        bm.close();
        meshCase(dir_, time_, mesh_);
    }

    static void TearDownTestSuite()
    {
        mesh_.reset();
        time_.reset();
    }

    static fs::path dir_;
    static std::unique_ptr<Foam::Time> time_;
    static std::unique_ptr<Foam::fvMesh> mesh_;
};

fs::path LShapedMesh::dir_;
std::unique_ptr<Foam::Time> LShapedMesh::time_;
std::unique_ptr<Foam::fvMesh> LShapedMesh::mesh_;


TEST_F(LShapedMesh, PointsInTheMissingSquareAreOutsideAndOthersInTheirCell)
{
    ASSERT_EQ(mesh_->nCells(), 48);
    const spoutlab::FoamCellLocator locator(*mesh_);
    const Foam::volVectorField& C = mesh_->C();
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int inHole = 0;
    for (int n = 0; n < 4000; ++n)
    {
        const spoutlab::Vec3 p{2*u(rng), u(rng), 2*u(rng)};
        const bool hole = p.x > 1 && p.z > 1;
        // hints: none, the corner cells next to the missing square, far
        for (const spoutlab::label hint : {-1, 0, 47, 20})
        {
            const spoutlab::label cell = locator.findCell(p, hint);
            if (hole)
            {
                EXPECT_EQ(cell, -1) << p.x << ' ' << p.z << " hint " << hint;
                continue;
            }
            ASSERT_GE(cell, 0) << p.x << ' ' << p.z;
            // cells are 0.25 x 1 x 0.25
            EXPECT_LE(std::abs(p.x - C[cell].x()), 0.125 + 1e-12);
            EXPECT_LE(std::abs(p.z - C[cell].z()), 0.125 + 1e-12);
        }
        inHole += hole;
    }
    EXPECT_GT(inHole, 500);           // the hole was really probed
}

TEST_F(LShapedMesh, BoxesOfOneSpacingAreALattice)
{
    EXPECT_TRUE(spoutlab::FoamCellLocator(*mesh_).onLattice());
}


TEST_F(LShapedMesh, PointsOnFacesGoToTheHintOrAnAdjacentCell)
{
    const spoutlab::FoamCellLocator locator(*mesh_);
    const Foam::volVectorField& C = mesh_->C();
    // the cells either side of the face x = 0.25 in the first row
    spoutlab::label left = -1, right = -1;
    forAll(C, c)
    {
        if (std::abs(C[c].z() - 0.125) > 1e-9) continue;
        if (std::abs(C[c].x() - 0.125) < 1e-9) left = c;
        if (std::abs(C[c].x() - 0.375) < 1e-9) right = c;
    }
    ASSERT_GE(left, 0);
    ASSERT_GE(right, 0);
    const spoutlab::Vec3 onFace{0.25, 0.5, 0.1};
    EXPECT_EQ(locator.findCell(onFace, left), left);
    EXPECT_EQ(locator.findCell(onFace, right), right);
    const spoutlab::label any = locator.findCell(onFace, -1);
    EXPECT_TRUE(any == left || any == right) << any;

    // on the outer boundary and on the missing square's faces: inside;
    // a micrometre beyond them: outside
    for (const spoutlab::Vec3& p :
         {spoutlab::Vec3{0.0, 0.5, 0.5}, spoutlab::Vec3{2.0, 0.5, 0.5},
          spoutlab::Vec3{0.5, 1.0, 0.5}, spoutlab::Vec3{1.5, 0.5, 1.0},
          spoutlab::Vec3{1.0, 0.5, 1.5}})
    {
        const spoutlab::label cell = locator.findCell(p, -1);
        ASSERT_GE(cell, 0) << p.x << ' ' << p.y << ' ' << p.z;
        EXPECT_LE(std::abs(p.x - C[cell].x()), 0.125 + 1e-12);
        EXPECT_LE(std::abs(p.z - C[cell].z()), 0.125 + 1e-12);
        EXPECT_EQ(locator.findCell(p, cell), cell);
    }
    const double e = 1e-6;
    for (const spoutlab::Vec3& p :
         {spoutlab::Vec3{-e, 0.5, 0.5}, spoutlab::Vec3{2 + e, 0.5, 0.5},
          spoutlab::Vec3{0.5, 1 + e, 0.5}, spoutlab::Vec3{1.5, 0.5, 1 + e},
          spoutlab::Vec3{1 + e, 0.5, 1.5}})
    {
        EXPECT_EQ(locator.findCell(p, -1), -1) << p.x << ' ' << p.y << ' ' << p.z;
        EXPECT_EQ(locator.findCell(p, 47), -1) << p.x << ' ' << p.y << ' ' << p.z;
    }
}

// n sample points of a unit sphere: random directions, at random depths
std::vector<spoutlab::Vec3> randomUnits(std::mt19937& rng, std::size_t n)
{
    std::uniform_real_distribution<double> u(0.0, 1.0), direction(-1.0, 1.0);
    std::vector<spoutlab::Vec3> units;
    while (units.size() < n)
    {
        const spoutlab::Vec3 v{direction(rng), direction(rng), direction(rng)};
        const double m = spoutlab::mag(v);
        if (m > 0.1 && m <= 1) units.push_back(v*(u(rng)/m));
    }
    return units;
}

TEST_F(LShapedMesh, SamplePointsOfASphereAreInFindCellsCells)
{
    // findCells looks a particle's sample points up from the centre's box;
    // each answer must be findCell's with the centre's cell as hint, for
    // spheres cut by faces, by the missing square and by the outer boundary
    const spoutlab::FoamCellLocator locator(*mesh_);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const std::vector<spoutlab::Vec3> units(randomUnits(rng, 40));
    std::vector<spoutlab::label> cells;
    int cut = 0;
    for (int n = 0; n < 2000; ++n)
    {
        const spoutlab::Vec3 x{2*u(rng), u(rng), 2*u(rng)};
        const spoutlab::label centre = locator.findCell(x, -1);
        if (centre < 0) continue;
        const double radius = 0.2*u(rng);
        locator.findCells(x, radius, units, centre, cells);
        ASSERT_EQ(cells.size(), units.size());
        for (std::size_t k = 0; k < units.size(); ++k)
        {
            const spoutlab::Vec3 p = x + units[k]*radius;
            EXPECT_EQ(cells[k], locator.findCell(p, centre))
                << p.x << ' ' << p.y << ' ' << p.z;
            cut += cells[k] != centre;
        }
    }
    EXPECT_GT(cut, 5000);   // many sample points left the centre's cell
}

TEST_F(LShapedMesh, ASpheresSamplePointsClearanceIsTheirSmallest)
{
    // the lattice's clearance of all sample points at once against the
    // point-by-point one, for spheres cut by faces, by the missing square
    // and by the outer boundary: equal to round-off (positions in lattice
    // coordinates taken once from the centre's)
    const spoutlab::FoamCellLocator locator(*mesh_);
    ASSERT_TRUE(locator.onLattice());
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const std::vector<spoutlab::Vec3> units(randomUnits(rng, 24));
    std::vector<spoutlab::label> cells;
    int outside = 0, open = 0;
    for (int n = 0; n < 3000; ++n)
    {
        const spoutlab::Vec3 x{2*u(rng), u(rng), 2*u(rng)};
        const spoutlab::label centre = locator.findCell(x, -1);
        if (centre < 0) continue;
        const double radius = 0.2*u(rng);
        locator.findCells(x, radius, units, centre, cells);
        double smallest = 1e300;
        for (std::size_t k = 0; k < units.size(); ++k)
        {
            smallest = std::min(smallest, locator.clearance(x + units[k]*radius, cells[k]));
            outside += cells[k] < 0;
        }
        EXPECT_NEAR(locator.clearance(x, radius, units, cells), smallest, 1e-12)
            << x.x << ' ' << x.y << ' ' << x.z << ' ' << radius;
        open += smallest > 1e-3;
    }
    EXPECT_GT(outside, 100);   // sample points in the hole and outside
    EXPECT_GT(open, 1000);     // and clearances worth keeping a row for
}

TEST_F(LShapedMesh, APointMovedLessThanItsClearanceKeepsItsCell)
{
    // in a cell, in the missing square and outside the mesh: moved less
    // than the clearance in any direction, findCell (hint: its cell) gives
    // the same answer -- what lets a particle keep last step's cells
    const spoutlab::FoamCellLocator locator(*mesh_);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-0.05, 1.05), d(-1.0, 1.0);
    int moved = 0, outside = 0;
    for (int n = 0; n < 3000; ++n)
    {
        const spoutlab::Vec3 p{2*u(rng), u(rng), 2*u(rng)};
        const spoutlab::label cell = locator.findCell(p, -1);
        const double c = locator.clearance(p, cell);
        EXPECT_LE(c, 0.125 + 1e-12);
        outside += cell < 0 && c > 0;
        for (int k = 0; k < 10 && c > 0; ++k, ++moved)
        {
            spoutlab::Vec3 dir{d(rng), d(rng), d(rng)};
            dir = dir/spoutlab::mag(dir);
            const spoutlab::Vec3 q = p + dir*(0.999*c);
            EXPECT_EQ(locator.findCell(q, cell), cell) << q.x << ' ' << q.y << ' ' << q.z;
        }
    }
    EXPECT_GT(moved, 25000);
    EXPECT_GT(outside, 300);   // the hole and the outside were probed too
}

} // namespace
