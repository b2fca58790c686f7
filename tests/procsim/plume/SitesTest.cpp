// Terrain grids and the placement of sources on the Eulerian grid.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "common/Cli.hpp"
#include "plume/EulerianCase.hpp"

using namespace procsim::plume;

TEST(EsriGrid, ReadsRowsNorthFirstAndCellCentres)
{
    const auto path = (std::filesystem::temp_directory_path() / "plume_esri_test.asc").string();
    {
        std::ofstream f(path);
        f << "ncols 3\nnrows 2\nxllcenter 50\nyllcenter 50\ncellsize 100\nNODATA_value -9999\n"
             "10 20 30\n1 2 3\n";
    }
    const EsriGrid g = readEsriGrid(path);
    EXPECT_DOUBLE_EQ(g.xll, 0.0);   // centre of the lower-left cell at 50 -> corner at 0
    EXPECT_DOUBLE_EQ(g.at(0, 0), 1.0);    // southern row is the last one written
    EXPECT_DOUBLE_EQ(g.at(2, 1), 30.0);
    EXPECT_DOUBLE_EQ(g.sample(150, 50), 2.0);
    EXPECT_DOUBLE_EQ(g.sample(100, 100), 0.25 * (1 + 2 + 10 + 20));   // bilinear
    std::remove(path.c_str());
}

TEST(EsriGrid, NodataIsAnError)
{
    const auto path = (std::filesystem::temp_directory_path() / "plume_esri_nodata.asc").string();
    {
        std::ofstream f(path);
        f << "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 10\nNODATA_value -9999\n1 2\n-9999 3\n";
    }
    EXPECT_THROW(readEsriGrid(path), procsim::InputError);
    std::remove(path.c_str());
}

TEST(Sources, AreaAndVolumeEmissionsAreConservedAndReduced)
{
    TerrainGrid g(20, 16, 8, 0.0, 0.0, 50.0, 50.0, 600.0, 2.0,
                  [](double x, double y) { return 100 + 0.1 * x - 0.05 * y; });
    Source a;
    a.name = "A";
    a.type = Source::Type::Area;
    a.x = 333;
    a.y = 401;
    a.lx = 170;
    a.ly = 90;
    a.height = 3;
    a.rate = 0.01;
    Source v = a;
    v.name = "V";
    v.type = Source::Type::Volume;
    v.bottom = 0;
    v.top = 40;
    v.rate = 0.004;
    v.controlled = false;   // not subject to the cut
    const auto q = distributeSources(g, {a, v}, 0.8);
    double total = 0;
    for (double x : q) total += x;
    EXPECT_NEAR(total, 0.01 * 0.2 + 0.004, 1e-15);
    // the area source sits in the lowest layer only
    double ground = 0;
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) ground += q[g.idx(i, j, 0)];
    EXPECT_GT(ground, 0.002 - 1e-15);
    Source out = a;
    out.x = 990;   // extends past x = 1000
    EXPECT_THROW(distributeSources(g, {out}, 0.0), procsim::InputError);
}
