/*---------------------------------------------------------------------------*\
    SpoutLab: particle location on an OpenFOAM mesh.
\*---------------------------------------------------------------------------*/
#include "FoamCellLocator.H"
#include "volFields.H"

#include <cmath>

namespace spoutlab
{

FoamCellLocator::FoamCellLocator(const Foam::fvMesh& mesh)
:
    mesh_(mesh),
    search_(mesh, Foam::polyMesh::FACE_PLANES),
    planeStart_(mesh.nCells() + 1, 0),
    cellCells_(mesh.nCells() + 1, 0)
{
    // Each cell's face planes (outward unit normal n, offset n.Cf) packed
    // together: locating a particle sample point is the hot loop of the
    // coupling, and this keeps it to a few dot products in one cache line.
    const Foam::cellList& cells = mesh.cells();
    for (Foam::label c = 0; c < mesh.nCells(); ++c)
    {
        planeStart_[c + 1] = planeStart_[c] + cells[c].size();
    }
    planes_.resize(planeStart_.back());
    faceCell_.resize(planeStart_.back());
    for (Foam::label c = 0; c < mesh.nCells(); ++c)
    {
        std::size_t k = planeStart_[c];
        for (const Foam::label f : cells[c])
        {
            Foam::vector n = mesh.faceAreas()[f];
            n /= Foam::mag(n);
            const bool owner = mesh.faceOwner()[f] == c;
            if (!owner) n = -n;
            faceCell_[k] = !mesh.isInternalFace(f) ? -1
                : (owner ? mesh.faceNeighbour()[f] : mesh.faceOwner()[f]);
            planes_[k++] = Plane{n.x(), n.y(), n.z(), n & mesh.faceCentres()[f]};
        }
    }
    const Foam::boundBox bb(mesh.points(), false);   // this rank's cells
    const double tol = 1e-9*bb.mag();
    bbMin_ = Vec3{bb.min().x() - tol, bb.min().y() - tol, bb.min().z() - tol};
    bbMax_ = Vec3{bb.max().x() + tol, bb.max().y() + tol, bb.max().z() + tol};

    const Foam::labelListList& nbrs = mesh.cellCells();
    for (Foam::label c = 0; c < mesh.nCells(); ++c)
    {
        cellCells_[c + 1] = cellCells_[c] + nbrs[c].size();
    }
    neighbours_.reserve(cellCells_.back());
    for (const auto& list : nbrs)
    {
        for (const Foam::label n : list) neighbours_.push_back(n);
    }
    buildLattice();
}


label FoamCellLocator::nCells() const
{
    return mesh_.nCells() + label(haloVolume_.size());
}


double FoamCellLocator::cellVolume(label cell) const
{
    return cell < mesh_.nCells() ? mesh_.V()[cell] : haloVolume_[cell - mesh_.nCells()];
}


double FoamCellLocator::depthInside(const Vec3& p, label cell) const
{
    double depth = 1e300;
    for (std::size_t k = planeStart_[cell]; k < planeStart_[cell + 1]; ++k)
    {
        const Plane& f = planes_[k];
        depth = std::min(depth, f.d - (f.nx*p.x + f.ny*p.y + f.nz*p.z));
    }
    return depth;
}


bool FoamCellLocator::inside(const Vec3& p, label cell) const
{
    // on a face counts as inside (both neighbours claim it; the first
    // tried wins, so the answer is stable for a given hint)
    for (std::size_t k = planeStart_[cell]; k < planeStart_[cell + 1]; ++k)
    {
        const Plane& f = planes_[k];
        if (f.nx*p.x + f.ny*p.y + f.nz*p.z > f.d) return false;
    }
    return true;
}


label FoamCellLocator::towards(const Vec3& p, label cell) const
{
    double furthest = 0;
    label next = cell;
    for (std::size_t k = planeStart_[cell]; k < planeStart_[cell + 1]; ++k)
    {
        const Plane& f = planes_[k];
        const double beyond = f.nx*p.x + f.ny*p.y + f.nz*p.z - f.d;
        if (beyond > furthest)
        {
            furthest = beyond;
            next = faceCell_[k];
        }
    }
    return next;
}


label FoamCellLocator::findCell(const Vec3& p, label hint) const
{
    if (onLattice())
    {
        // on a face counts as inside, and the hint is tried first, as in
        // the walk below
        return hint >= 0 && inside(p, hint) ? hint : findOnLattice(p, hint);
    }
    if (hint >= mesh_.nCells())
    {
        // an atom that strayed into a neighbour's cell, or its sample points
        if (inside(p, hint)) return hint;
        hint = -1;
    }
    const label cell = findOwned(p, hint);
    return cell >= 0 || haloVolume_.empty() ? cell : findHalo(p);
}


void FoamCellLocator::findCells
(
    const Vec3& x, double radius, const std::vector<Vec3>& units,
    label centre, std::vector<label>& cells
) const
{
    cells.resize(units.size());
    if
    (
        onLattice() && centre >= 0 && centre < nCells()
     && findCellsOnLattice(x, radius, units, centre, cells)
    )
    {
        return;
    }
    constexpr std::size_t maxCut = 32;
    std::size_t cut[maxCut];
    std::size_t nCut = 0;
    bool fast = centre >= 0 && centre < mesh_.nCells();
    for (std::size_t k = planeStart_[fast ? centre : 0]; fast && k < planeStart_[centre + 1]; ++k)
    {
        const Plane& f = planes_[k];
        if (f.d - (f.nx*x.x + f.ny*x.y + f.nz*x.z) >= radius) continue;
        if (nCut == maxCut) fast = false;
        else cut[nCut++] = k;
    }
    for (std::size_t i = 0; i < units.size(); ++i)
    {
        const Vec3 p = x + units[i]*radius;
        bool inCentre = fast;
        for (std::size_t j = 0; inCentre && j < nCut; ++j)
        {
            const Plane& f = planes_[cut[j]];
            inCentre = f.nx*p.x + f.ny*p.y + f.nz*p.z <= f.d;
        }
        cells[i] = inCentre ? centre : findCell(p, centre);
    }
}


label FoamCellLocator::findHalo(const Vec3& p) const
{
    if
    (
        p.x < haloBbMin_.x || p.y < haloBbMin_.y || p.z < haloBbMin_.z
     || p.x > haloBbMax_.x || p.y > haloBbMax_.y || p.z > haloBbMax_.z
    )
    {
        return -1;
    }
    for (std::size_t k = 0; k < haloVolume_.size(); ++k)
    {
        const Vec3& lo = haloMin_[k];
        const Vec3& hi = haloMax_[k];
        if (p.x < lo.x || p.y < lo.y || p.z < lo.z || p.x > hi.x || p.y > hi.y || p.z > hi.z)
        {
            continue;
        }
        const label cell = mesh_.nCells() + label(k);
        if (inside(p, cell)) return cell;
    }
    return -1;
}


label FoamCellLocator::findOwned(const Vec3& p, label hint) const
{
    // sample points of particles cut by a wall often lie outside the whole
    // mesh: no search needed
    if
    (
        p.x < bbMin_.x || p.y < bbMin_.y || p.z < bbMin_.z
     || p.x > bbMax_.x || p.y > bbMax_.y || p.z > bbMax_.z
    )
    {
        return -1;
    }
    if (hint >= 0)
    {
        // the walk ends in the one cell holding p (cells do not overlap),
        // or gives up at a boundary face (a hole or a non-convex corner of
        // the mesh may lie between) or after a few steps
        label cell = hint;
        for (int step = 0; step < 4 && cell >= 0; ++step)
        {
            const label next = towards(p, cell);
            if (next == cell) return cell;
            cell = next;
        }
        for (std::size_t k = cellCells_[hint]; k < cellCells_[hint + 1]; ++k)
        {
            if (inside(p, neighbours_[k])) return neighbours_[k];
        }
    }
    const Foam::point q(p.x, p.y, p.z);
    const label cell = search_.findCell(q, -1, true);
    if (cell >= 0) return cell;

    // The octree may miss a point lying on a boundary face to within
    // round-off; accept the hint (or the nearest cell) if the point is that
    // close to it.
    const label candidate = hint >= 0 ? hint : search_.findNearestCell(q, -1, true);
    if (candidate < 0) return -1;
    const double tolerance = 1e-9*std::cbrt(mesh_.V()[candidate]);
    return depthInside(p, candidate) >= -tolerance ? candidate : -1;
}


bool FoamCellLocator::cellBoxes(std::vector<double>& lo, std::vector<double>& hi) const
{
    // each cell's bounds from its face planes; every plane must face along
    // an axis (a box; split faces of one side give the same plane)
    const label n = nCells();
    lo.assign(3*n, 1e300);
    hi.assign(3*n, -1e300);
    for (label c = 0; c < n; ++c)
    {
        for (std::size_t k = planeStart_[c]; k < planeStart_[c + 1]; ++k)
        {
            const double nk[3] = {planes_[k].nx, planes_[k].ny, planes_[k].nz};
            int axis = -1;
            for (int a = 0; a < 3; ++a)
            {
                if (std::abs(std::abs(nk[a]) - 1) < 1e-9) axis = a;
                else if (std::abs(nk[a]) > 1e-9) return false;
            }
            if (axis < 0) return false;
            if (nk[axis] > 0) hi[3*c + axis] = std::max(hi[3*c + axis], planes_[k].d);
            else lo[3*c + axis] = std::min(lo[3*c + axis], -planes_[k].d);
        }
    }
    return true;
}


void FoamCellLocator::buildLattice()
{
    lattice_ = Lattice();
    const label n = nCells();
    std::vector<double> lo, hi;
    if (n == 0 || !cellBoxes(lo, hi)) return;

    // one spacing per axis, every box at a whole number of spacings from
    // the lowest corner
    Lattice L;
    for (int a = 0; a < 3; ++a)
    {
        L.spacing[a] = hi[a] - lo[a];
        L.origin[a] = 1e300;
        double top = -1e300;
        for (label c = 0; c < n; ++c)
        {
            if (std::abs(hi[3*c + a] - lo[3*c + a] - L.spacing[a]) > 1e-6*L.spacing[a]) return;
            L.origin[a] = std::min(L.origin[a], lo[3*c + a]);
            top = std::max(top, hi[3*c + a]);
        }
        L.n[a] = std::lround((top - L.origin[a])/L.spacing[a]);
        L.inverse[a] = 1/L.spacing[a];
    }
    if (double(L.n[0])*double(L.n[1])*double(L.n[2]) > 64.0*double(n) + 1e4) return;
    L.cell.assign(std::size_t(L.n[0]*L.n[1]*L.n[2]), -1);
    L.box.resize(std::size_t(n));
    for (label c = 0; c < n; ++c)
    {
        std::array<long, 3>& index = L.box[c];
        for (int a = 0; a < 3; ++a)
        {
            const double t = (lo[3*c + a] - L.origin[a])/L.spacing[a];
            index[a] = std::lround(t);
            if (std::abs(t - double(index[a])) > 1e-6) return;
        }
        label& box = L.cell[std::size_t(index[0] + L.n[0]*(index[1] + L.n[1]*index[2]))];
        if (box >= 0) return;   // two cells in one box: not a lattice
        box = c;
    }
    lattice_ = std::move(L);
}


label FoamCellLocator::latticeCell(const Vec3& p) const
{
    const Lattice& L = lattice_;
    const double x[3] = {p.x, p.y, p.z};
    long index[3];
    for (int a = 0; a < 3; ++a)
    {
        const double t = (x[a] - L.origin[a])/L.spacing[a];
        if (t < -1e-9 || t > double(L.n[a]) + 1e-9) return -1;
        index[a] = std::min(std::max(long(std::floor(t)), 0L), L.n[a] - 1);
    }
    return L.cell[std::size_t(index[0] + L.n[0]*(index[1] + L.n[1]*index[2]))];
}


label FoamCellLocator::findOnLattice(const Vec3& p, label hint) const
{
    const label cell = latticeCell(p);
    if (cell >= 0 && inside(p, cell)) return cell;

    // Within round-off of a box face the index and the face planes can
    // disagree: the boxes around hold the point.
    const Lattice& L = lattice_;
    const double x[3] = {p.x, p.y, p.z};
    bool nearFace = false;
    for (int a = 0; a < 3; ++a)
    {
        const double t = (x[a] - L.origin[a])/L.spacing[a];
        const double f = t - std::floor(t);
        nearFace = nearFace || f < 1e-6 || f > 1 - 1e-6;
    }
    for (int dz = -1; nearFace && dz <= 1; ++dz)
    {
        for (int dy = -1; dy <= 1; ++dy)
        {
            for (int dx = -1; dx <= 1; ++dx)
            {
                const Vec3 q
                {
                    p.x + dx*1e-6*L.spacing[0], p.y + dy*1e-6*L.spacing[1],
                    p.z + dz*1e-6*L.spacing[2]
                };
                const label c = latticeCell(q);
                if (c >= 0 && inside(p, c)) return c;
            }
        }
    }
    // a point on the mesh boundary to within round-off: the hint (or the
    // box's cell) if the point is that close to it, as findOwned
    const label candidate = hint >= 0 ? hint : cell;
    if (candidate < 0) return -1;
    const double tolerance = 1e-9*std::cbrt(cellVolume(candidate));
    return depthInside(p, candidate) >= -tolerance ? candidate : -1;
}


bool FoamCellLocator::findCellsOnLattice
(
    const Vec3& x, double radius, const std::vector<Vec3>& units,
    label centre, std::vector<label>& cells
) const
{
    // the centre in its box's coordinates (0 to 1), the radius in boxes;
    // only the axes along which the sphere reaches a face of the box can
    // move a piece out of it (usually one or two of the three)
    const Lattice& L = lattice_;
    const std::array<long, 3>& box = L.box[centre];
    const double xc[3] = {x.x, x.y, x.z};
    const long stride[3] = {1, L.n[0], L.n[0]*L.n[1]};
    struct Cut { int axis; double f, r; bool below, above; };
    Cut cut[3];
    int nCut = 0;
    for (int a = 0; a < 3; ++a)
    {
        const double f = (xc[a] - L.origin[a])*L.inverse[a] - double(box[a]);
        const double r = radius*L.inverse[a];
        if (r >= 1) return false;
        if (f - r < 0 || f + r > 1)
        {
            // whether the boxes below and above exist in the lattice
            cut[nCut++] = Cut{a, f, r, box[a] > 0, box[a] < L.n[a] - 1};
        }
    }
    const long home = box[0] + L.n[0]*(box[1] + L.n[1]*box[2]);
    for (std::size_t i = 0; i < units.size(); ++i)
    {
        const double u[3] = {units[i].x, units[i].y, units[i].z};
        long index = home;
        bool outside = false;
        for (int j = 0; j < nCut; ++j)
        {
            // on a face counts as in the centre's box, as findCells' planes
            const Cut& c = cut[j];
            const double t = c.f + c.r*u[c.axis];
            if (t < 0)
            {
                outside = outside || !c.below;
                index -= stride[c.axis];
            }
            else if (t > 1)
            {
                outside = outside || !c.above;
                index += stride[c.axis];
            }
        }
        cells[i] = outside ? -1 : L.cell[std::size_t(index)];
    }
    return true;
}


double FoamCellLocator::latticeClearance(const double t[3]) const
{
    // in boxes (a cell's box faces are its face planes, to round-off);
    // latticeCell takes points up to 1e-9 box beyond the lattice as on it.
    // Floor by truncation, the cheaper, corrected below zero.
    const Lattice& L = lattice_;
    double inside = 1e300, beyond = 0;
    for (int a = 0; a < 3; ++a)
    {
        const double out = std::max(-t[a], t[a] - double(L.n[a])) - 1e-9;
        beyond = std::max(beyond, out*L.spacing[a]);
        double below = double(long(t[a]));
        if (below > t[a]) below -= 1;
        const double f = t[a] - below;
        inside = std::min(inside, std::min(f, 1 - f)*L.spacing[a]);
    }
    return beyond > 0 ? beyond : inside;
}


double FoamCellLocator::clearance(const Vec3& p, label cell) const
{
    if (!onLattice()) return cell >= 0 ? std::max(0.0, depthInside(p, cell)) : 0;
    const Lattice& L = lattice_;
    const double x[3] = {p.x, p.y, p.z};
    double t[3];
    for (int a = 0; a < 3; ++a) t[a] = (x[a] - L.origin[a])*L.inverse[a];
    return latticeClearance(t);
}


double FoamCellLocator::clearance
(
    const Vec3& centre, double radius, const std::vector<Vec3>& units,
    const std::vector<label>& cells
) const
{
    if (!onLattice()) return CellLocator::clearance(centre, radius, units, cells);
    // clearance(point, cell) point by point, in lattice coordinates taken
    // once from the centre's (they differ from the point's own by
    // round-off, far below rowLasts' margin)
    const Lattice& L = lattice_;
    const double xc[3] = {centre.x, centre.y, centre.z};
    double tc[3], reach[3];
    for (int a = 0; a < 3; ++a)
    {
        tc[a] = (xc[a] - L.origin[a])*L.inverse[a];
        reach[a] = radius*L.inverse[a];
    }
    double smallest = 1e300;
    for (std::size_t k = 0; k < units.size() && smallest > 0; ++k)
    {
        const double u[3] = {units[k].x, units[k].y, units[k].z};
        const double t[3] = {tc[0] + reach[0]*u[0], tc[1] + reach[1]*u[1], tc[2] + reach[2]*u[2]};
        smallest = std::min(smallest, latticeClearance(t));
    }
    return smallest;
}


bool FoamCellLocator::sphereInsideCell
(
    label cell, const Vec3& centre, double radius
) const
{
    return depthInside(centre, cell) >= radius;
}

// --- the halo ------------------------------------------------------------------

namespace
{

// each cell's bounds, from its faces' points
void cellBounds(const Foam::fvMesh& mesh, Foam::label c, Vec3& lo, Vec3& hi)
{
    lo = Vec3{1e300, 1e300, 1e300};
    hi = Vec3{-1e300, -1e300, -1e300};
    for (const Foam::label f : mesh.cells()[c])
    {
        for (const Foam::label pt : mesh.faces()[f])
        {
            const Foam::point& x = mesh.points()[pt];
            lo = Vec3{std::min(lo.x, x.x()), std::min(lo.y, x.y()), std::min(lo.z, x.z())};
            hi = Vec3{std::max(hi.x, x.x()), std::max(hi.y, x.y()), std::max(hi.z, x.z())};
        }
    }
}

// Send and receive one message with each neighbour.
void swap
(
    const std::vector<int>& rank, const std::vector<std::vector<double>>& out,
    std::vector<std::vector<double>>& in
)
{
    std::vector<MPI_Request> requests(2*rank.size());
    for (std::size_t s = 0; s < rank.size(); ++s)
    {
        MPI_Irecv
        (
            in[s].data(), int(in[s].size()), MPI_DOUBLE, rank[s], 7101,
            MPI_COMM_WORLD, &requests[2*s]
        );
        MPI_Isend
        (
            const_cast<double*>(out[s].data()), int(out[s].size()), MPI_DOUBLE,
            rank[s], 7101, MPI_COMM_WORLD, &requests[2*s + 1]
        );
    }
    MPI_Waitall(int(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
}


// Whether an own cell lies within reach of the neighbouring box at offset
// d (-1, 0, 1 along each axis) of this rank's box: of each plane shared
// with it
bool nearBox
(
    const ProcessorGrid& grid, const std::array<int, 3>& box,
    const std::array<int, 3>& d, const Vec3& lo, const Vec3& hi, double reach
)
{
    const double low[3] = {lo.x, lo.y, lo.z}, high[3] = {hi.x, hi.y, hi.z};
    for (int a = 0; a < 3; ++a)
    {
        const std::vector<double>& cuts = grid.cuts[a];
        if (d[a] < 0 && low[a] > cuts[std::size_t(box[a] - 1)] + reach) return false;
        if (d[a] > 0 && high[a] < cuts[std::size_t(box[a])] - reach) return false;
    }
    return true;
}

} // namespace


void FoamCellLocator::addHalo(const ProcessorGrid& grid, double reach)
{
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    const std::array<int, 3>& box = grid.box[std::size_t(rank)];

    // the boxes around this one (diagonal too), in rank order, and the own
    // cells within reach of each
    std::vector<std::array<int, 3>> offsets(std::size_t(grid.box.size()));
    sides_.clear();
    for (std::size_t r = 0; r < grid.box.size(); ++r)
    {
        bool next = int(r) != rank;
        for (int a = 0; a < 3; ++a)
        {
            offsets[r][a] = grid.box[r][a] - box[a];
            next = next && std::abs(offsets[r][a]) <= 1;
        }
        if (next) sides_.push_back(Side{int(r), {}, 0, 0});
    }
    for (Foam::label c = 0; c < mesh_.nCells(); ++c)
    {
        Vec3 lo, hi;
        cellBounds(mesh_, c, lo, hi);
        for (Side& side : sides_)
        {
            const std::array<int, 3>& d = offsets[std::size_t(side.rank)];
            if (nearBox(grid, box, d, lo, hi, reach)) side.sent.push_back(c);
        }
    }

    // their geometry both ways: first the sizes, then the cells
    const std::size_t n = sides_.size();
    std::vector<std::vector<double>> out(n), in(n), sizesOut(n), sizesIn(n);
    std::vector<int> ranks(n);
    for (std::size_t s = 0; s < n; ++s)
    {
        ranks[s] = sides_[s].rank;
        out[s] = packedCells(sides_[s].sent);
        sizesOut[s] = {double(out[s].size()), double(sides_[s].sent.size())};
        sizesIn[s].assign(2, 0.0);
    }
    swap(ranks, sizesOut, sizesIn);
    for (std::size_t s = 0; s < n; ++s) in[s].resize(std::size_t(sizesIn[s][0]));
    swap(ranks, out, in);

    // append the received cells after our own, side by side
    haloBbMin_ = Vec3{1e300, 1e300, 1e300};
    haloBbMax_ = Vec3{-1e300, -1e300, -1e300};
    for (std::size_t s = 0; s < n; ++s)
    {
        sides_[s].haloStart = haloVolume_.size();
        sides_[s].haloSize = std::size_t(sizesIn[s][1]);
        appendHaloCells(in[s], sides_[s].haloSize);
    }
    buildLattice();
}


std::vector<double> FoamCellLocator::packedCells(const std::vector<label>& cells) const
{
    // per cell: volume, bounds (6), number of faces, face planes (4 each)
    std::vector<double> out;
    for (const label c : cells)
    {
        Vec3 lo, hi;
        cellBounds(mesh_, c, lo, hi);
        out.insert(out.end(), {mesh_.V()[c], lo.x, lo.y, lo.z, hi.x, hi.y, hi.z});
        out.push_back(double(planeStart_[c + 1] - planeStart_[c]));
        for (std::size_t k = planeStart_[c]; k < planeStart_[c + 1]; ++k)
        {
            const Plane& f = planes_[k];
            out.insert(out.end(), {f.nx, f.ny, f.nz, f.d});
        }
    }
    return out;
}


void FoamCellLocator::appendHaloCells(const std::vector<double>& packed, std::size_t n)
{
    std::size_t k = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const double* cell = &packed[k];
        haloVolume_.push_back(cell[0]);
        const double tol = 1e-9*std::cbrt(cell[0]);
        haloMin_.push_back(Vec3{cell[1] - tol, cell[2] - tol, cell[3] - tol});
        haloMax_.push_back(Vec3{cell[4] + tol, cell[5] + tol, cell[6] + tol});
        const Vec3& lo = haloMin_.back();
        const Vec3& hi = haloMax_.back();
        haloBbMin_ = Vec3{std::min(haloBbMin_.x, lo.x), std::min(haloBbMin_.y, lo.y), std::min(haloBbMin_.z, lo.z)};
        haloBbMax_ = Vec3{std::max(haloBbMax_.x, hi.x), std::max(haloBbMax_.y, hi.y), std::max(haloBbMax_.z, hi.z)};
        const std::size_t nFaces = std::size_t(cell[7]);
        for (std::size_t f = 0; f < nFaces; ++f)
        {
            const double* pl = &cell[8 + 4*f];
            planes_.push_back(Plane{pl[0], pl[1], pl[2], pl[3]});
            faceCell_.push_back(-1);   // no walks through the halo
        }
        planeStart_.push_back(planes_.size());
        cellCells_.push_back(cellCells_.back());
        k += 8 + 4*nFaces;
    }
}


void FoamCellLocator::exchange
(
    std::vector<double>& values, int width, bool reverse
) const
{
    const std::size_t w = std::size_t(width), nOwned = std::size_t(mesh_.nCells());
    const std::size_t n = sides_.size();
    std::vector<std::vector<double>> out(n), in(n);
    std::vector<int> ranks(n);
    for (std::size_t s = 0; s < n; ++s)
    {
        const Side& side = sides_[s];
        ranks[s] = side.rank;
        if (reverse)
        {
            // our halo cells' shares go to their owner
            const double* halo = &values[(nOwned + side.haloStart)*w];
            out[s].assign(halo, halo + side.haloSize*w);
            in[s].resize(side.sent.size()*w);
        }
        else
        {
            for (const label c : side.sent)
            {
                out[s].insert(out[s].end(), &values[c*w], &values[c*w] + w);
            }
            in[s].resize(side.haloSize*w);
        }
    }
    swap(ranks, out, in);
    for (std::size_t s = 0; s < n; ++s)
    {
        traffic_.messages += 1;
        traffic_.bytes += double(out[s].size()*sizeof(double));
    }
    for (std::size_t s = 0; s < n; ++s)
    {
        const Side& side = sides_[s];
        if (reverse)
        {
            for (std::size_t i = 0; i < side.sent.size(); ++i)
            {
                for (std::size_t d = 0; d < w; ++d)
                {
                    values[side.sent[i]*w + d] += in[s][i*w + d];
                }
            }
        }
        else
        {
            std::copy(in[s].begin(), in[s].end(), &values[(nOwned + side.haloStart)*w]);
        }
    }
}


void FoamCellLocator::complete(std::vector<double>& values, int width) const
{
    if (sides_.empty()) return;
    exchange(values, width, true);
    exchange(values, width, false);
}


std::vector<double> FoamCellLocator::withHalo(const Foam::scalarField& field) const
{
    std::vector<double> values(static_cast<std::size_t>(nCells()), 0.0);
    std::copy(field.begin(), field.end(), values.begin());
    if (!sides_.empty()) exchange(values, 1, false);
    return values;
}


std::vector<Vec3> FoamCellLocator::withHalo(const Foam::vectorField& field) const
{
    std::vector<double> flat(3*static_cast<std::size_t>(nCells()), 0.0);
    forAll(field, i)
    {
        flat[3*i] = field[i].x();
        flat[3*i + 1] = field[i].y();
        flat[3*i + 2] = field[i].z();
    }
    if (!sides_.empty()) exchange(flat, 3, false);
    std::vector<Vec3> values(flat.size()/3);
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        values[i] = Vec3{flat[3*i], flat[3*i + 1], flat[3*i + 2]};
    }
    return values;
}

} // namespace spoutlab
