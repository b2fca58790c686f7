/*---------------------------------------------------------------------------*\
    SpoutLab: particle location on an OpenFOAM mesh.
\*---------------------------------------------------------------------------*/
#include "FoamCellLocator.H"
#include "volFields.H"

namespace spoutlab
{

FoamCellLocator::FoamCellLocator(const Foam::fvMesh& mesh)
:
    mesh_(mesh),
    search_(mesh, Foam::polyMesh::FACE_PLANES)
{}


label FoamCellLocator::nCells() const
{
    return mesh_.nCells();
}


double FoamCellLocator::cellVolume(label cell) const
{
    return mesh_.V()[cell];
}


bool FoamCellLocator::inside(const Foam::point& p, label cell) const
{
    return mesh_.pointInCell(p, Foam::label(cell), Foam::polyMesh::FACE_PLANES);
}


label FoamCellLocator::findCell(const Vec3& q, label hint) const
{
    const Foam::point p(q.x, q.y, q.z);
    if (hint >= 0)
    {
        if (inside(p, hint)) return hint;
        for (const Foam::label nbr : mesh_.cellCells()[hint])
        {
            if (inside(p, nbr)) return nbr;
        }
    }
    const label cell = search_.findCell(p, -1, true);
    if (cell >= 0) return cell;
    // The octree may miss a point lying exactly on a boundary face; the
    // nearest cell's own (inclusive) face-plane test settles it.
    // The octree may miss a point lying on a boundary face to within
    // round-off; accept the nearest cell if the point is that close to it.
    const label nearest = search_.findNearestCell(p, -1, true);
    if (nearest < 0) return -1;
    const double tolerance = 1e-9*std::cbrt(mesh_.V()[nearest]);
    return depthInside(p, nearest) >= -tolerance ? nearest : -1;
}


double FoamCellLocator::depthInside(const Foam::point& p, label cell) const
{
    double depth = 1e300;
    for (const Foam::label facei : mesh_.cells()[cell])
    {
        Foam::vector n = mesh_.faceAreas()[facei];
        n /= Foam::mag(n);
        if (mesh_.faceOwner()[facei] != cell) n = -n;   // make it outward
        depth = std::min(depth, double((mesh_.faceCentres()[facei] - p) & n));
    }
    return depth;
}


bool FoamCellLocator::sphereInsideCell
(
    label cell, const Vec3& c, double radius
) const
{
    return depthInside(Foam::point(c.x, c.y, c.z), cell) >= radius;
}

} // namespace spoutlab
