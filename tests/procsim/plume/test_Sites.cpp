// Terrain grids and the placement of sources on the Eulerian grid.
#include <gtest/gtest.h>

#include <algorithm>
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
    EXPECT_DOUBLE_EQ(g.xll, 0.0);      // centre of the lower-left cell at 50 -> corner at 0
    EXPECT_DOUBLE_EQ(g.at(0, 0), 1.0); // southern row is the last one written
    EXPECT_DOUBLE_EQ(g.at(2, 1), 30.0);
    EXPECT_DOUBLE_EQ(g.sample(150, 50), 2.0);
    EXPECT_DOUBLE_EQ(g.sample(100, 100), 0.25 * (1 + 2 + 10 + 20)); // bilinear
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

namespace
{

// The message readEsriGrid refuses `text` with ("" if it reads it).
std::string refusal(const std::string& text)
{
    const auto path = (std::filesystem::temp_directory_path() / "plume_esri_bad.asc").string();
    {
        std::ofstream f(path);
        f << text;
    }
    std::string message;
    try
    {
        readEsriGrid(path);
    }
    catch (const procsim::InputError& e)
    {
        message = e.what();
    }
    std::remove(path.c_str());
    return message;
}

} // namespace

// Each refusal is one line naming the file, the line and the key or value.
TEST(EsriGrid, BadHeaderOrRowNamesTheLine)
{
    const std::string header =
        "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 10\nNODATA_value -9999\n";
    const auto endsWith = [](const std::string& message, const std::string& tail) {
        return message.size() >= tail.size()
               && message.compare(message.size() - tail.size(), tail.size(), tail) == 0;
    };
    EXPECT_PRED2(endsWith, refusal(header + "ncols 4\n1 2 3\n"),
                 ".asc: line 7: header key 'ncols' is given twice");
    EXPECT_PRED2(endsWith, refusal("ncols 3\nnrows 2\nfoo 1\n"),
                 ".asc: line 3: unknown header key 'foo' (expected ncols, nrows, xllcorner, yllcorner, "
                 "cellsize, NODATA_value)");
    EXPECT_PRED2(endsWith, refusal("ncols 3.5\n"),
                 ".asc: line 1: header key 'ncols' expected a whole number from 2 to 100000, got '3.5'");
    EXPECT_PRED2(endsWith, refusal(header + "1 2 3\n4 5\n"),
                 ".asc: line 8: expected 3 values (ncols), got 2");
    EXPECT_PRED2(endsWith, refusal(header + "1 2 3\n4 5 6\n7 8 9\n"), ".asc: expected 2 rows (nrows), got 3");
    EXPECT_PRED2(endsWith, refusal(header), ".asc: no elevation rows after the header");
}

namespace
{

// 20 x 16 columns of 50 m on a tilted plane, 8 stretched levels up to 600 m
TerrainGrid tiltedGrid()
{
    return TerrainGrid(20, 16, 8, 0.0, 0.0, 50.0, 50.0, 600.0, 2.0,
                       [](double x, double y) { return 100 + 0.1 * x - 0.05 * y; });
}

Source areaSource()
{
    Source a;
    a.name = "A";
    a.type = Source::Type::Area;
    a.x = 333; // x 248..418, y 356..446 m
    a.y = 401;
    a.lx = 170;
    a.ly = 90;
    a.height = 3; // below the lowest cell centre (~10 m) everywhere
    a.rate = 0.01;
    return a;
}

Source volumeSource()
{
    Source v = areaSource();
    v.name = "V";
    v.type = Source::Type::Volume;
    v.bottom = 0;
    v.top = 40;
    v.height = 20;
    v.rate = 0.004;
    v.controlled = false; // not subject to the cut
    return v;
}

double sum(const std::vector<double>& q)
{
    double s = 0;
    for (double x : q) s += x;
    return s;
}

} // namespace

// Each source separately, so that neither can meet the other's check: the
// area source puts all of its (reduced) emission into the lowest layer, each
// column its share of the footprint (column (6, 7): x 300..350 m inside,
// y 350..400 m of which 356..400 inside, so 50 x 44 m of 170 x 90 m);
// the volume source shares each column's part among the layers by the
// overlap of [bottom, top] with the layer's height range.
TEST(Sources, AreaSourceFillsTheGroundLayerByFootprint)
{
    const TerrainGrid g = tiltedGrid();
    const auto q = distributeSources(g, {areaSource()}, 0.8);
    const double emitted = 0.01 * 0.2;
    EXPECT_NEAR(sum(q), emitted, 1e-15);
    double ground = 0;
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) ground += q[g.idx(i, j, 0)];
    EXPECT_NEAR(ground, emitted, 1e-15); // nothing above the lowest layer
    EXPECT_NEAR(q[g.idx(6, 7, 0)], emitted * 50 * 44 / (170 * 90), 1e-15);
    // column (4, 7) spans x 200..250 and holds the strip 248..250
    EXPECT_NEAR(q[g.idx(4, 7, 0)], emitted * 2 * 44 / (170 * 90), 1e-15);
    EXPECT_EQ(q[g.idx(3, 7, 0)], 0.0);
}

TEST(Sources, VolumeSourceSharedByHeightOverlap)
{
    const TerrainGrid g = tiltedGrid();
    const auto q = distributeSources(g, {volumeSource()}, 0.8);
    EXPECT_NEAR(sum(q), 0.004, 1e-15); // uncontrolled: no cut
    const double column = 0.004 * 50 * 44 / (170 * 90);
    const double d = g.depth(6, 7);
    double inColumn = 0;
    for (int k = 0; k < g.nz; ++k)
    {
        const double lo = d * g.fFace[k], hi = d * g.fFace[k + 1];
        const double overlap = std::max(0.0, std::min(hi, 40.0) - std::max(lo, 0.0));
        EXPECT_NEAR(q[g.idx(6, 7, k)], column * overlap / 40, 1e-15) << "layer " << k;
        inColumn += q[g.idx(6, 7, k)];
    }
    EXPECT_NEAR(inColumn, column, 1e-15);
    ASSERT_GT(d * g.fFace[1], 0.0);
    ASSERT_LT(d * g.fFace[1], 40.0); // the source reaches above the lowest layer
    EXPECT_GT(q[g.idx(6, 7, 1)], 0.0);
}

TEST(Sources, SourcesAddAndOneOutsideIsAnError)
{
    const TerrainGrid g = tiltedGrid();
    const auto a = distributeSources(g, {areaSource()}, 0.8);
    const auto v = distributeSources(g, {volumeSource()}, 0.8);
    const auto both = distributeSources(g, {areaSource(), volumeSource()}, 0.8);
    for (std::size_t n = 0; n < both.size(); ++n) ASSERT_NEAR(both[n], a[n] + v[n], 1e-18);
    Source out = areaSource();
    out.x = 990; // extends past x = 1000
    EXPECT_THROW(distributeSources(g, {out}, 0.0), procsim::InputError);
}

// A point source is spread by trilinear weights: whatever the position, the
// cells receive exactly its emission, none a negative share, and inside the
// grid (between the outermost cell centres) their emission-weighted mean
// position is the source's own -- in x, y and in the height above ground.
// Positions: on a cell corner (faces in x, y and an s-level), at a cell
// centre, in general, close to a lateral boundary, below the lowest cell
// centre (all into the lowest cells) and near the lid.
TEST(Sources, PointSourceTrilinearConservesEmissionAndPosition)
{
    const TerrainGrid g = tiltedGrid();
    struct Case
    {
        double x, y, height;
        bool interior; // between the outermost centres in every direction
    };
    const double faceHeight = g.depth(6, 7) * g.fFace[3]; // an s-level over column (6, 7)
    const Case cases[] = {{300, 350, faceHeight, true}, {325, 375, g.depth(6, 7) * g.fCell[2], true},
                          {433.3, 512.7, 47.1, true},   {10, 790, 30, false},
                          {612, 244, 2.0, false},       {140, 160, 440, false}};
    for (const auto& c : cases)
    {
        Source p;
        p.name = "P";
        p.type = Source::Type::Point;
        p.x = c.x;
        p.y = c.y;
        p.height = c.height;
        p.rate = 0.003;
        const auto q = distributeSources(g, {p}, 0.0);
        double total = 0, mx = 0, my = 0, mz = 0;
        int cells = 0;
        for (int k = 0; k < g.nz; ++k)
            for (int j = 0; j < g.ny; ++j)
                for (int i = 0; i < g.nx; ++i)
                {
                    const double w = q[g.idx(i, j, k)];
                    ASSERT_GE(w, 0.0);
                    if (w == 0) continue;
                    ++cells;
                    total += w;
                    mx += w * g.xc(i);
                    my += w * g.yc(j);
                    mz += w * g.heightAboveGround(i, j, k);
                }
        const std::string at =
            std::to_string(c.x) + ", " + std::to_string(c.y) + ", " + std::to_string(c.height);
        EXPECT_NEAR(total, 0.003, 1e-17) << at;
        EXPECT_LE(cells, 8) << at;
        if (c.interior)
        {
            EXPECT_NEAR(mx / total, c.x, 1e-9) << at;
            EXPECT_NEAR(my / total, c.y, 1e-9) << at;
            // the heights are interpolated within each column, so the mean
            // height above ground is the release height wherever the terrain
            EXPECT_NEAR(mz / total, c.height, 1e-9) << at;
        }
    }
    // on a corner of cells, all eight cells share it
    Source corner;
    corner.type = Source::Type::Point;
    corner.x = 300;
    corner.y = 350;
    corner.height = 47.1;
    corner.rate = 1;
    int cells = 0;
    for (double w : distributeSources(g, {corner}, 0.0)) cells += w > 0;
    EXPECT_EQ(cells, 8);
}
