#pragma once
// Eulerian PM10 transport (eq 3 of the Saraburi paper) in terrain-following
// coordinates, finite volumes on a grid that is uniform in the computational
// coordinates (xi = x, eta = y, s in [0,1]):
//
//     z(x, y, s) = h(x, y) + D(x, y) f(s),    D = z_top - h,
//
// with f(s) a vertical stretching (f(0) = 0, f(1) = 1).  x points east, y
// north, z up (the paper's y is up; its K_V acts along our z).
//
// Fluxes are volume fluxes through the faces of the physical (curvilinear)
// cells, so conservation is exact: the change of the total mass equals the
// sources minus what leaves through open boundaries, to round-off.
//
//   advection  : QUICK face values with a TVD limiter (see faceValue), upwind
//                at boundaries; inflow carries the background concentration.
//   diffusion  : K_H along the horizontal, K_V along the vertical, with the
//                cross terms of the coordinate transform (they vanish on flat
//                terrain, where the scheme is the Cartesian one).
//   time       : second-order Adams-Bashforth; the very first step is forward
//                Euler, later steps carry AB2 across the hourly wind changes.
//                Optionally (setImplicitVertical) the direct vertical diffusion
//                term is taken by Crank-Nicolson, one tridiagonal solve per
//                column (IMEX AB2/CN, still second order and conservative):
//                thin near-ground cells and K_H acting along steep terrain
//                (K_H z_x^2 / dz^2) otherwise force sub-second steps.
#include <memory>
#include <string>
#include <vector>

namespace procsim::plume
{

struct EsriGrid;

// Vertical stretching f(s) = (exp(beta s) - 1) / (exp(beta) - 1); beta = 0 is uniform.
double stretch(double s, double beta);

class TerrainGrid
{
public:
    // Columns of size dx x dy starting at (x0, y0); terrain h given at cell
    // centres (nx*ny) and sampled by `terrainAt` at face centres.
    template <class TerrainFn>
    TerrainGrid(int nx, int ny, int nz, double x0, double y0, double dx, double dy, double zTop, double beta,
                TerrainFn terrainAt)
        : nx(nx), ny(ny), nz(nz), x0(x0), y0(y0), dx(dx), dy(dy), zTop(zTop), beta(beta)
    {
        hc.resize(static_cast<std::size_t>(nx) * ny);
        hxf.resize(static_cast<std::size_t>(nx + 1) * ny);
        hyf.resize(static_cast<std::size_t>(nx) * (ny + 1));
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) hc[col(i, j)] = terrainAt(xc(i), yc(j));
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i <= nx; ++i) hxf[j * (nx + 1) + i] = terrainAt(x0 + i * dx, yc(j));
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i < nx; ++i) hyf[j * nx + i] = terrainAt(xc(i), y0 + j * dy);
        build();
    }

    // Flat, uniform box (Cartesian grid) of height zTop above h = elevation.
    static TerrainGrid box(int nx, int ny, int nz, double x0, double y0, double dx, double dy, double zTop,
                           double elevation = 0.0);

    int nx, ny, nz;
    double x0, y0, dx, dy, zTop, beta;
    std::vector<double> fFace; // f at the nz+1 level faces
    std::vector<double> fCell; // f at cell centres (mid-face in s)
    std::vector<double> hc;    // terrain at column centres
    std::vector<double> hxf;   // terrain at x-face centres ((nx+1)*ny)
    std::vector<double> hyf;   // terrain at y-face centres (nx*(ny+1))

    std::size_t size() const { return static_cast<std::size_t>(nx) * ny * nz; }
    std::size_t col(int i, int j) const { return static_cast<std::size_t>(j) * nx + i; }
    std::size_t idx(int i, int j, int k) const { return (static_cast<std::size_t>(k) * ny + j) * nx + i; }
    double xc(int i) const { return x0 + (i + 0.5) * dx; }
    double yc(int j) const { return y0 + (j + 0.5) * dy; }
    double depth(int i, int j) const { return zTop - hc[col(i, j)]; }
    double zc(int i, int j, int k) const { return hc[col(i, j)] + depth(i, j) * fCell[k]; }
    double heightAboveGround(int i, int j, int k) const { return depth(i, j) * fCell[k]; }
    double volume(int i, int j, int k) const { return dx * dy * depth(i, j) * (fFace[k + 1] - fFace[k]); }
    bool containsXY(double x, double y) const
    {
        return x >= x0 && x <= x0 + nx * dx && y >= y0 && y <= y0 + ny * dy;
    }

private:
    void build();
};

// Volume fluxes [m^3/s] through the faces, positive along +x, +y, +s.
struct Flow
{
    std::vector<double> fx; // (nx+1)*ny*nz, index (k*ny + j)*(nx+1) + i
    std::vector<double> fy; // nx*(ny+1)*nz, index (k*(ny+1) + j)*nx + i
    std::vector<double> fs; // nx*ny*(nz+1), index (k*ny + j)*nx + i
    double maxTopFlux = 0;  // |flux| left at the top after the adjustment (diagnostic)

    static Flow zero(const TerrainGrid& g);
};

// Wind from a measurement at `zRef` above ground (speed, direction the wind
// blows FROM, degrees clockwise from north) extended by the power law
// U(z') = U_ref (z'/zRef)^p over the height above ground z', integrated
// exactly over each face.  Then made mass-consistent: the column-integrated
// horizontal flow gets the smallest correction (in the D-weighted least-squares
// sense) that makes it divergence-free, u = u0 + grad(lambda) with
// div(D grad lambda) = -div(D u0) and lambda = 0 on the open lateral
// boundaries; the correction is uniform over each column.  The flux through
// the s-surfaces is then diagnosed from continuity cell by cell from the
// ground up, so every cell is divergence-free and nothing crosses the lid.
class WindModel
{
public:
    WindModel(const TerrainGrid& grid, double exponent, double zRef);
    Flow flow(double speedRef, double directionFromDeg) const;

private:
    const TerrainGrid& g_;
    double p_, zRef_;
    struct Impl;
    std::shared_ptr<Impl> impl_;
};

enum class Advection
{
    LimitedQuick,
    Quick,
    Upwind
};

// The transport solver.
class Transport
{
public:
    // trueHorizontal: K_H acts along true horizontal planes (full transform,
    // metric cross terms included); false: along the terrain-following
    // surfaces (the cross terms and the K_H z_x^2 vertical part dropped).
    // The cross terms are explicit and indefinite on their own, so the full
    // transform must be run with the vertical diffusion explicit.
    Transport(const TerrainGrid& grid, double kH, double kV, Advection scheme = Advection::LimitedQuick,
              bool trueHorizontal = true);

    void setFlow(const Flow& flow);
    void setSources(std::vector<double> kgPerS); // per cell [kg/s]
    void setBackground(double kgPerM3) { background_ = kgPerM3; }
    void setImplicitVertical(bool on);
    bool implicitVertical() const { return implicit_; }

    // Largest stable time step for the current flow: AB2 is stable for a
    // real eigenvalue lambda dt >= -1, so per cell
    //   dt <= 1 / ( 4 (K_H/dx^2 + K_H/dy^2 + K_zz/dz^2) + sum_faces |F| / V )
    // with dz the cell's physical thickness, K_zz = K_V + K_H |grad h|^2 (1-f)^2
    // the vertical diffusivity of the transformed equation and sum |F| / V
    // (= 2|u|/dx in 1D) from the face fluxes.  The K_zz term is dropped when
    // the vertical diffusion is implicit.
    double stableDt() const;

    void step(double dt);
    double time() const { return time_; }

    std::vector<double> c;                              // concentration [kg/m^3]
    double mass() const;                                // sum of C V [kg]
    double boundaryOutflow() const { return outflow_; } // mass that left [kg]

    // Concentration at (x, y) and height above ground [m]; bilinear between
    // columns, linear in the height above ground (constant below the first
    // cell centre).
    double sample(double x, double y, double heightAboveGround) const;

    const TerrainGrid& grid() const { return g_; }

private:
    const TerrainGrid& g_;
    double kH_, kV_;
    Advection scheme_;
    Flow flow_;
    std::vector<double> src_;
    std::vector<double> vol_;
    std::vector<double> rPrev_, r_;
    std::vector<double> gz_, gxs_, gys_; // cell gradients used by the cross terms
    // face diffusion coefficients
    std::vector<double> axF_, bxF_; // x faces: a (C_R - C_L) and b * dC/dz
    std::vector<double> ayF_, byF_;
    std::vector<double> asF_, bsxF_, bsyF_;
    double background_ = 0;
    double time_ = 0;
    double outflow_ = 0;
    double lastOut_ = 0, prevOut_ = 0;
    bool first_ = true;
    bool implicit_ = false;
    bool trueHorizontal_ = true;
    std::vector<double> rhsCol_, aCol_, bCol_, cCol_;

    void residual(std::vector<double>& r);
    void crossTermGradients();
    void xFaceFluxes(std::vector<double>& r, double& out) const;
    void yFaceFluxes(std::vector<double>& r, double& out) const;
    void sFaceFluxes(std::vector<double>& r, double& out) const;
};

} // namespace procsim::plume
