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
    const Foam::boundBox& bb = mesh.bounds();
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
}


label FoamCellLocator::nCells() const
{
    return mesh_.nCells();
}


double FoamCellLocator::cellVolume(label cell) const
{
    return mesh_.V()[cell];
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


bool FoamCellLocator::sphereInsideCell
(
    label cell, const Vec3& centre, double radius
) const
{
    return depthInside(centre, cell) >= radius;
}

} // namespace spoutlab
