// The plume grid's ParaView files read back through VTK's own readers: the
// terrain-following corners against a planar terrain, the cell values in
// VTK's cell order, the compressed appended layout, the .pvd collection.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include <gtest/gtest.h>
#include <unistd.h>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkStructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLStructuredGridReader.h>

#include "plume/Eulerian.hpp"
#include "plume/Vtk.hpp"

namespace fs = std::filesystem;
using namespace procsim::plume;

namespace
{

double terrain(double x, double y)
{
    return 100.0 + 0.05 * x + 0.02 * y;
}

struct PlumeVts : ::testing::Test
{
    // stretched levels (beta 1.5) over a tilted plane
    TerrainGrid g{6, 4, 5, -300.0, 200.0, 100.0, 150.0, 1000.0, 1.5, terrain};
    fs::path dir = fs::temp_directory_path() / ("plumeVts_" + std::to_string(::getpid()));
    std::vector<double> values;

    void SetUp() override
    {
        fs::remove_all(dir);
        fs::create_directories(dir);
        for (std::size_t n = 0; n < g.size(); ++n) values.push_back(1.0 + 0.37 * n);
        writeVts((dir / "C_1h.vts").string(), g, "PM10_ug_m3", values);
    }
    void TearDown() override { fs::remove_all(dir); }

    vtkSmartPointer<vtkStructuredGrid> read() const
    {
        vtkNew<vtkXMLStructuredGridReader> reader;
        reader->SetFileName((dir / "C_1h.vts").c_str());
        reader->Update();
        EXPECT_EQ(reader->GetErrorCode(), 0u);
        return reader->GetOutput();
    }
};

// a corner's terrain is the mean of the columns around it, which on a plane
// is the plane at the mean of their centres
double cornerTerrain(const TerrainGrid& g, int i, int j)
{
    const double x = 0.5 * (g.xc(std::max(i - 1, 0)) + g.xc(std::min(i, g.nx - 1)));
    const double y = 0.5 * (g.yc(std::max(j - 1, 0)) + g.yc(std::min(j, g.ny - 1)));
    return terrain(x, y);
}

} // namespace

TEST_F(PlumeVts, CornersFollowTheTerrain)
{
    auto grid = read();
    int dims[3];
    grid->GetDimensions(dims);
    ASSERT_EQ(dims[0], g.nx + 1);
    ASSERT_EQ(dims[1], g.ny + 1);
    ASSERT_EQ(dims[2], g.nz + 1);
    EXPECT_EQ(grid->GetPoints()->GetDataType(), VTK_DOUBLE);
    vtkIdType n = 0;
    for (int k = 0; k <= g.nz; ++k)
        for (int j = 0; j <= g.ny; ++j)
            for (int i = 0; i <= g.nx; ++i)
            {
                double p[3];
                grid->GetPoint(n++, p);
                const double h = cornerTerrain(g, i, j);
                EXPECT_NEAR(p[0], -300.0 + 100.0 * i, 1e-12);
                EXPECT_NEAR(p[1], 200.0 + 150.0 * j, 1e-12);
                EXPECT_NEAR(p[2], h + (1000.0 - h) * g.fFace[k], 1e-9) << i << ' ' << j << ' ' << k;
            }
    double bottom[3], top[3];
    grid->GetPoint(0, bottom);
    grid->GetPoint(n - 1, top);
    EXPECT_NEAR(bottom[2], terrain(g.xc(0), g.yc(0)), 1e-9); // the ground
    EXPECT_NEAR(top[2], 1000.0, 1e-9);                       // the lid
}

TEST_F(PlumeVts, CellValuesInPlace)
{
    auto grid = read();
    vtkDataArray* c = grid->GetCellData()->GetArray("PM10_ug_m3");
    ASSERT_NE(c, nullptr);
    ASSERT_EQ(c->GetNumberOfTuples(), vtkIdType(g.size()));
    EXPECT_EQ(grid->GetCellData()->GetScalars(), c);
    const double ulp = std::numeric_limits<float>::epsilon();
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i)
            {
                const std::size_t n = g.idx(i, j, k);
                // the cell VTK holds at n lies over column (i, j)
                double b[6];
                grid->GetCell(vtkIdType(n))->GetBounds(b);
                EXPECT_TRUE(b[0] < g.xc(i) && g.xc(i) < b[1] && b[2] < g.yc(j) && g.yc(j) < b[3]);
                EXPECT_NEAR(c->GetTuple1(vtkIdType(n)), values[n], 0.5 * ulp * values[n]);
            }
}

TEST_F(PlumeVts, CompressedAppended)
{
    std::ifstream in(dir / "C_1h.vts", std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
    EXPECT_NE(text.find("<AppendedData encoding=\"raw\">"), std::string::npos);
    EXPECT_FALSE(fs::exists(dir / "C_1h.vts.tmp"));
}

TEST_F(PlumeVts, CollectionListsTheSnapshots)
{
    writePvd((dir / "C.pvd").string(), {{3600.0, "vts/C_1h.vts"}, {7200.0, "vts/C_2h.vts"}});
    vtkNew<vtkXMLDataParser> parser;
    parser->SetFileName((dir / "C.pvd").c_str());
    ASSERT_EQ(parser->Parse(), 1);
    vtkXMLDataElement* collection = parser->GetRootElement()->FindNestedElementWithName("Collection");
    ASSERT_NE(collection, nullptr);
    ASSERT_EQ(collection->GetNumberOfNestedElements(), 2);
    EXPECT_EQ(std::stod(collection->GetNestedElement(1)->GetAttribute("timestep")), 7200.0);
    EXPECT_EQ(std::string(collection->GetNestedElement(1)->GetAttribute("file")), "vts/C_2h.vts");
}
