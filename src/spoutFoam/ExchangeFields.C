/*---------------------------------------------------------------------------*\
    SpoutLab: the cell fields the particles give the gas.
\*---------------------------------------------------------------------------*/
#include "ExchangeFields.H"

namespace spoutlab
{

namespace
{

// A cell field the coupling computes and writes with the gas fields.
Foam::IOobject outputField(const Foam::fvMesh& mesh, const Foam::word& name)
{
    return Foam::IOobject
    (
        name, mesh.time().timeName(), mesh,
        Foam::IOobject::NO_READ, Foam::IOobject::AUTO_WRITE
    );
}

} // namespace


ExchangeFields::ExchangeFields(const Foam::fvMesh& mesh)
:
    mesh_(mesh),
    Ksl_
    (
        outputField(mesh, "Ksl"), mesh,
        Foam::dimensionedScalar(Foam::dimDensity/Foam::dimTime, Foam::Zero)
    ),
    Us_
    (
        outputField(mesh, "Us"), mesh,
        Foam::dimensionedVector(Foam::dimVelocity, Foam::Zero)
    ),
    solidFraction_
    (
        outputField(mesh, "solidFraction"), mesh,
        Foam::dimensionedScalar(Foam::dimless, Foam::Zero)
    ),
    solidFlux_
    (
        outputField(mesh, "solidFlux"), mesh,
        Foam::dimensionedVector(Foam::dimVelocity, Foam::Zero)
    )
{}


void ExchangeFields::update(const ExchangeResult& ex)
{
    forAll(Ksl_, celli)
    {
        Ksl_[celli] = ex.beta[celli];
        const Vec3& us = ex.Us[celli];
        Us_[celli] = Foam::vector(us.x, us.y, us.z);
        solidFraction_[celli] = ex.solidFraction[celli];
        solidFlux_[celli] = ex.solidFraction[celli]*Us_[celli];
    }
    Ksl_.correctBoundaryConditions();
    Us_.correctBoundaryConditions();
    solidFraction_.correctBoundaryConditions();
    solidFlux_.correctBoundaryConditions();
}


Vec3 ExchangeFields::gasMomentum(const Foam::volVectorField& U) const
{
    // the momentum equation's exchange term Ksl (Us - U) is implicit in U,
    // so what it took is this sum with the U it returned
    Vec3 received;
    forAll(Ksl_, celli)
    {
        const Foam::vector d = Ksl_[celli]*mesh_.V()[celli]*(U[celli] - Us_[celli]);
        received += Vec3{d.x(), d.y(), d.z()};
    }
    return received;
}


void ExchangeFields::write() const
{
    Ksl_.write();
    Us_.write();
    solidFraction_.write();
}

} // namespace spoutlab
