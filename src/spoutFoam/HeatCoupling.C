/*---------------------------------------------------------------------------*\
    SpoutLab: gas-to-particle heat transfer on the CFD side.
\*---------------------------------------------------------------------------*/
#include "HeatCoupling.H"
#include "RangeWarnings.H"

#include "FluxVelocity.H"
#include "FoamParameters.H"
#include "InputError.hpp"
#include "OStringStream.H"
#include "RunGuards.H"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace spoutlab
{

namespace
{

GasThermalProperties readGas(const Foam::fvMesh& mesh, double rho, double mu)
{
    const Foam::IOdictionary transport
    (
        Foam::IOobject
        (
            "transportProperties", mesh.time().constant(), mesh,
            Foam::IOobject::MUST_READ, Foam::IOobject::NO_WRITE, false
        )
    );
    const std::string file = "constant/transportProperties";
    return GasThermalProperties
    {
        rho, mu,
        positiveEntry(transport, file, "Cp", "the gas specific heat c_p [J/kg/K], a positive number"),
        positiveEntry(transport, file, "kappa", "the gas thermal conductivity k_c [W/m/K], a positive number")
    };
}


Foam::IOobject writtenField(const Foam::fvMesh& mesh, const Foam::word& name)
{
    return Foam::IOobject
    (
        name, mesh.time().timeName(), mesh,
        Foam::IOobject::NO_READ, Foam::IOobject::AUTO_WRITE
    );
}


Foam::IOobject scratchField(const Foam::fvMesh& mesh, const Foam::word& name)
{
    return Foam::IOobject
    (
        name, mesh.time().timeName(), mesh,
        Foam::IOobject::NO_READ, Foam::IOobject::NO_WRITE
    );
}


const Foam::dimensionSet dimHeatPerVolume(1, -1, -3, 0, 0);            // W/m3
const Foam::dimensionSet dimHeatPerVolumeKelvin(1, -1, -3, -1, 0);     // W/m3/K

} // namespace


std::unique_ptr<HeatCoupling> HeatCoupling::New
(
    const Foam::fvMesh& mesh,
    const FoamCellLocator& cells,
    const Foam::dictionary& couplingDict,
    const LiggghtsDem& dem,
    const std::string& liggghtsInput,
    const Foam::volScalarField& voidfraction,
    const Foam::surfaceScalarField& phi,
    double rho,
    double mu
)
{
    const Foam::word model =
        couplingDict.getOrDefault<Foam::word>("heatTransferModel", "none");
    if (model == "none") return nullptr;
    // a bad name before what LIGGGHTS lacks for heat: the name is fixed first
    HeatTransferModel::registry().require(model, "constant/couplingProperties");
    if (!dem.hasHeat())
    {
        throw InputError
        (
            "LIGGGHTS input '" + liggghtsInput + "': heat transfer "
            "(heatTransferModel " + model + " in constant/couplingProperties) "
            "expects the particle temperatures of 'fix ID all couple/cfd/"
            "convection T0 <K>' and 'fix ID all property/global "
            "thermalCapacity peratomtype ...'"
        );
    }
    std::unique_ptr<HeatCoupling> heat
    (
        new HeatCoupling(mesh, cells, couplingDict, model, voidfraction, phi, rho, mu)
    );
    Foam::Info<< "Heat transfer: " << model.c_str() << ", gas c_p "
        << heat->gas().cp << " J/kg/K, k_c " << heat->gas().kappa
        << " W/m/K" << Foam::endl;
    return heat;
}


HeatCoupling::HeatCoupling
(
    const Foam::fvMesh& mesh,
    const FoamCellLocator& cells,
    const Foam::dictionary& couplingDict,
    const Foam::word& modelName,
    const Foam::volScalarField& voidfraction,
    const Foam::surfaceScalarField& phi,
    double rho,
    double mu
)
:
    mesh_(mesh),
    locator_(cells),
    voidfraction_(voidfraction),
    phi_(phi),
    gas_(readGas(mesh, rho, mu)),
    exchange_
    (
        HeatTransferModel::New(modelName, toParameters(couplingDict, modelName + "Props"))
    ),
    T_
    (
        Foam::IOobject
        (
            "T", mesh.time().timeName(), mesh,
            Foam::IOobject::MUST_READ, Foam::IOobject::AUTO_WRITE
        ),
        mesh
    ),
    hp_
    (
        writtenField(mesh, "hp"), mesh,
        Foam::dimensionedScalar(Foam::dimensionSet(1, 0, -3, -1, 0), Foam::Zero)
    ),
    Rep_(writtenField(mesh, "Rep"), mesh, Foam::dimensionedScalar(Foam::dimless, Foam::Zero)),
    Qs_
    (
        writtenField(mesh, "Qs"), mesh,
        Foam::dimensionedScalar(dimHeatPerVolume, Foam::Zero)
    ),
    K_(scratchField(mesh, "Kheat"), mesh, Foam::dimensionedScalar(dimHeatPerVolumeKelvin, Foam::Zero)),
    S_(scratchField(mesh, "Sheat"), mesh, Foam::dimensionedScalar(dimHeatPerVolume, Foam::Zero))
{
    checkCase();
    centres_ = locator_.withHalo(mesh.C().primitiveField());
    for (const HeatTransferModel* c : exchange_.model().correlations())
    {
        ranges_.add(c->name(), c->statedRanges());
        reSlot_.push_back(ranges_.slot(c->name(), "Re"));
        voidageSlot_.push_back(ranges_.slot(c->name(), "voidage"));
    }
}


void HeatCoupling::checkCase() const
{
    checkStartField(T_);
    const double Tmin = Foam::gMin(T_.primitiveField());
    double TbMin = 1e300;
    forAll(T_.boundaryField(), patchi)
    {
        const Foam::scalarField& Tb = T_.boundaryField()[patchi];
        if (Tb.size()) TbMin = std::min(TbMin, Foam::min(Tb));
    }
    Foam::reduce(TbMin, Foam::minOp<double>());
    if (!(std::min(Tmin, TbMin) > 0))
    {
        throw InputError
        (
            mesh_.time().timeName() + "/T: expected absolute gas temperatures "
            "[K] above 0, got a minimum of " + std::to_string(std::min(Tmin, TbMin))
        );
    }
    if (!mesh_.solutionDict().subDict("solvers").found("T"))
    {
        throw InputError
        (
            "system/fvSolution: key 'solvers/T' is missing (heat transfer "
            "solves the gas temperature T)"
        );
    }
    const Foam::dictionary& div = mesh_.schemesDict().subDict("divSchemes");
    if (!div.found("div(phi,T)") && !div.found("default"))
    {
        throw InputError
        (
            "system/fvSchemes: key 'divSchemes/div(phi,T)' is missing (heat "
            "transfer convects the gas temperature T)"
        );
    }
}


void HeatCoupling::updateCoefficients
(
    const std::vector<Particle>& particles,
    const std::vector<double>& eps,
    const ParticleCellMap& map,
    const ExchangeResult& momentum
)
{
    // The slip is taken with the gas velocity the face fluxes carry,
    // reconstruct(phi)/eps: the fluxes satisfy continuity, while on a
    // collocated grid the cell-centred U of the momentum equation departs
    // from them where the drag changes steeply from cell to cell (in a
    // packed bed's bottom layer by 26 %, which put h 15 % below the
    // correlation's value at the bed's own superficial velocity).
    // FluxVelocity.H says why not fvc::reconstruct.
    const Foam::vectorField U
    (
        fluxVelocity(phi_)/Foam::max(voidfraction_.primitiveField(), Foam::SMALL)
    );
    cells_ = exchange_.cellCoefficients
    (
        locator_, particles, map, momentum,
        GasHeatCellFields{centres_, locator_.withHalo(U), eps}, gas_,
        humid_ ? humid_->vapourDiffusivity : 0.0
    );
    forAll(K_, i)
    {
        K_[i] = cells_.K[i];
        S_[i] = cells_.S[i];
        hp_[i] = cells_.h[i];
        Rep_[i] = cells_.reynolds[i];
    }
    K_.correctBoundaryConditions();
    S_.correctBoundaryConditions();
    hp_.correctBoundaryConditions();
    Rep_.correctBoundaryConditions();
    updateQs();
    watchRanges(eps);
}


void HeatCoupling::watchRanges(const std::vector<double>& eps)
{
    // the voidage the correlation saw (clipped as for the drag)
    if (ranges_.empty()) return;
    forAll(hp_, i)
    {
        const int c = cells_.correlation[i];
        if (c < 0) continue;
        ranges_.see(reSlot_[c], cells_.reynolds[i]);
        ranges_.see(voidageSlot_[c], eps[i]);
    }
    reportRanges(ranges_);
}


void HeatCoupling::useHumidGas(const HumidGas& humid)
{
    humid_.reset(new HumidGas(humid));
    epsCp_.reset
    (
        new Foam::volScalarField
        (
            Foam::IOobject
            (
                "epsCp", mesh_.time().timeName(), mesh_,
                Foam::IOobject::NO_READ, Foam::IOobject::NO_WRITE
            ),
            voidfraction_*humid.cp
        )
    );
    epsCp_->oldTime();
}


Foam::tmp<Foam::fvScalarMatrix> HeatCoupling::humidEnergyEquation()
{
    const Foam::dimensionedScalar rho("rho", Foam::dimDensity, gas_.rho);
    const Foam::dimensionedScalar kappa
    (
        "kappa", Foam::dimensionSet(1, 1, -3, -1, 0), gas_.kappa
    );
    *epsCp_ = voidfraction_*humid_->cp;   // the last step's becomes the old time
    const Foam::surfaceScalarField phiCp
    (
        "phiCp", phi_*Foam::fvc::interpolate(humid_->cp)
    );
    // conservative in eps c_p T, as the dry gas's equation is in eps T
    return
    (
        rho*(Foam::fvm::ddt(*epsCp_, T_) + Foam::fvm::div(phiCp, T_, "div(phi,T)"))
      - Foam::fvm::laplacian(kappa, T_)
     ==
        S_ + humid_->vapourEnthalpy - Foam::fvm::Sp(K_, T_)
    );
}


void HeatCoupling::solveGas()
{
    if (humid_)
    {
        humidEnergyEquation()->solve();
        updateQs();
        return;
    }
    const Foam::dimensionedScalar rhoCp
    (
        "rhoCp", Foam::dimensionSet(1, -1, -2, -1, 0), gas_.rho*gas_.cp
    );
    const Foam::dimensionedScalar kappa
    (
        "kappa", Foam::dimensionSet(1, 1, -3, -1, 0), gas_.kappa
    );
    // eq 4 times rho c_p, conservative in eps T so the energy the gas holds
    // changes exactly by what crosses the boundaries and what the particles
    // take (the log's balance depends on it)
    Foam::fvScalarMatrix TEqn
    (
        rhoCp*(Foam::fvm::ddt(voidfraction_, T_) + Foam::fvm::div(phi_, T_))
      - Foam::fvm::laplacian(kappa, T_)
     ==
        S_ - Foam::fvm::Sp(K_, T_)
    );
    TEqn.solve();
    updateQs();
}


void HeatCoupling::updateQs()
{
    Qs_.primitiveFieldRef() = S_.primitiveField() - K_.primitiveField()*T_.primitiveField();
    Qs_.correctBoundaryConditions();
}


std::vector<double> HeatCoupling::particleHeatFlux
(
    const std::vector<Particle>& particles,
    const ParticleCellMap& map
) const
{
    return exchange_.particleHeatFlux
    (
        particles, map, cells_, locator_.withHalo(T_.primitiveField())
    );
}


std::vector<double> HeatCoupling::particleH(const ParticleCellMap& map) const
{
    return HeatExchange::particleH(map, cells_);
}


void HeatCoupling::checkTimeStep(double minHeatCapacityPerArea) const
{
    const double hMax = Foam::gMax(hp_.primitiveField());
    if (!(hMax > 0)) return;
    const double tau = minHeatCapacityPerArea/hMax;
    const double dt = mesh_.time().deltaTValue();
    if (dt > 0.1*tau)
    {
        std::ostringstream os;
        os << "system/controlDict: key 'deltaT' expected at most 0.1 x the "
           << "shortest particle heating time m c_p/(h A) = " << tau
           << " s (h = " << hMax << " W/m2/K) for the explicit particle "
           << "temperature update, got " << dt << " s";
        throw InputError(os.str());
    }
}


GasHeatBalance HeatCoupling::balance() const
{
    // rho c_p of the gas per cell and boundary face: constant, or the humid
    // gas's c_p
    const double rhoCp = gas_.rho*gas_.cp;
    auto rhoCpAt = [&](Foam::label patchi, Foam::label facei)
    {
        return humid_ ? gas_.rho*humid_->cp.boundaryField()[patchi][facei] : rhoCp;
    };
    const Foam::scalarField& V = mesh_.V().field();
    GasHeatBalance b{0, 0, 0, 0, 0};
    double outFlux = 0, outFluxT = 0;
    forAll(T_.boundaryField(), patchi)
    {
        const Foam::fvPatchScalarField& Tb = T_.boundaryField()[patchi];
        if (Tb.coupled()) continue;
        const Foam::scalarField& phib = phi_.boundaryField()[patchi];
        const Foam::scalarField snGrad(Tb.snGrad());
        const Foam::scalarField& magSf = mesh_.magSf().boundaryField()[patchi];
        forAll(Tb, facei)
        {
            // what the discretised equation lets through this face, into
            // the gas: convection phi T (phi > 0 leaves) and conduction
            const double into =
                -rhoCpAt(patchi, facei)*phib[facei]*Tb[facei]
              + gas_.kappa*snGrad[facei]*magSf[facei];
            if (phib[facei] < 0) b.inflow += into;
            else b.outflow -= into;
            if (phib[facei] > 0)
            {
                outFlux += phib[facei];
                outFluxT += phib[facei]*Tb[facei];
            }
        }
    }
    forAll(V, i)
    {
        b.gasGave += V[i]*(K_[i]*T_[i] - S_[i]);
        b.gasEnergy += humid_
          ? gas_.rho*V[i]*(*epsCp_)[i]*T_[i]
          : rhoCp*V[i]*voidfraction_[i]*T_[i];
    }
    double sums[6] = {b.gasGave, b.inflow, b.outflow, b.gasEnergy, outFlux, outFluxT};
    for (double& s : sums) Foam::reduce(s, Foam::sumOp<double>());
    return GasHeatBalance
    {
        sums[0], sums[1], sums[2], sums[4] > 0 ? sums[5]/sums[4] : 0.0, sums[3]
    };
}

} // namespace spoutlab
