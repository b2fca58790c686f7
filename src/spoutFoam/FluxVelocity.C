/*---------------------------------------------------------------------------*\
    SpoutLab: the velocity the face fluxes carry (FluxVelocity.H).
\*---------------------------------------------------------------------------*/
#include "FluxVelocity.H"

namespace spoutlab
{

namespace
{

// 1 on the diagonal for each direction the mesh has no extent in (a 2-D
// mesh's empty direction): there sum |S| n n is 0, so the inverse is taken
// with 1 there and the 1 removed again, as fvc::reconstruct does
Foam::tensor missingDirections(const Foam::fvMesh& mesh)
{
    Foam::tensor missing(Foam::Zero);
    const Foam::Vector<Foam::label>& directions = mesh.geometricD();
    for (Foam::direction d = 0; d < Foam::vector::nComponents; ++d)
    {
        if (directions[d] == -1) missing(d, d) = 1;
    }
    return missing;
}

} // namespace


Foam::tmp<Foam::vectorField> fluxVelocity(const Foam::surfaceScalarField& phi)
{
    const Foam::fvMesh& mesh = phi.mesh();
    const Foam::surfaceVectorField n(mesh.Sf()/mesh.magSf());
    // sum_f |S_f| n_f n_f and sum_f n_f phi_f, each a field of its own, so
    // that the product below never writes into one of its operands
    const Foam::volTensorField areas(Foam::fvc::surfaceSum(n*mesh.Sf()));
    const Foam::volVectorField fluxes(Foam::fvc::surfaceSum(n*phi));
    const Foam::tensor missing = missingDirections(mesh);

    Foam::tmp<Foam::vectorField> tu(new Foam::vectorField(mesh.nCells()));
    Foam::vectorField& u = tu.ref();
    forAll(u, celli)
    {
        const Foam::tensor inverse = Foam::inv(areas[celli] + missing) - missing;
        u[celli] = inverse & fluxes[celli];
    }
    return tu;
}

} // namespace spoutlab
