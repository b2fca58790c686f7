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
    return search_.findCell(p, -1, true);
}


bool FoamCellLocator::sphereInsideCell
(
    label cell, const Vec3& c, double radius
) const
{
    const Foam::point centre(c.x, c.y, c.z);
    const Foam::labelList& faces = mesh_.cells()[cell];
    for (const Foam::label facei : faces)
    {
        Foam::vector n = mesh_.faceAreas()[facei];
        n /= Foam::mag(n);
        if (mesh_.faceOwner()[facei] != cell) n = -n;   // make it outward
        const double distance = (mesh_.faceCentres()[facei] - centre) & n;
        if (distance < radius) return false;
    }
    return true;
}

} // namespace spoutlab
