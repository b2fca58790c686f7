/*---------------------------------------------------------------------------*\
    SpoutLab: couplingProperties entries as Parameters.
\*---------------------------------------------------------------------------*/
#include "FoamParameters.H"

#include "OStringStream.H"

#include "CoarseGraining.hpp"
#include "InputError.hpp"

#include <cmath>
#include <limits>

namespace spoutlab
{

// An OpenFOAM sub-dictionary as the coupling library's Parameters.
Parameters toParameters(const Foam::dictionary& parent, const Foam::word& name)
{
    Parameters params("constant/couplingProperties/" + name);
    const Foam::dictionary* dict = parent.findDict(name);
    if (!dict) return params;
    for (const Foam::entry& e : *dict)
    {
        if (e.isDict()) continue;
        std::string value;
        const Foam::ITstream& is = e.stream();
        forAll(is, i)
        {
            if (i) value += ' ';
            const Foam::token& t = is[i];
            if (t.isStringType())
            {
                value += t.stringToken();   // words and strings, unquoted
            }
            else
            {
                Foam::OStringStream os;
                os << t;
                value += os.str();
            }
        }
        params.set(e.keyword(), value);
    }
    return params;
}


double positiveEntry
(
    const Foam::dictionary& dict,
    const std::string& file,
    const Foam::word& key,
    const std::string& what,
    const std::string& needed
)
{
    const Foam::entry* e = dict.findEntry(key, Foam::keyType::LITERAL);
    std::string got;
    if (e && !e->isDict())
    {
        Foam::ITstream& is = e->stream();
        if (is.size() == 1 && is[0].isNumber())
        {
            const double value = is[0].number();
            if (value > 0 && std::isfinite(value)) return value;
        }
        Foam::OStringStream os;
        forAll(is, i) os << (i ? " " : "") << is[i];
        got = os.str();
    }
    throw InputError
    (
        file + ": key '" + key + "' expected " + what
      + (e ? ", got '" + got + "'" : " (missing; " + needed + " needs it)")
    );
}


double coarseGrainingEntry(const Foam::dictionary& dict, const std::string& file)
{
    const Foam::entry* e = dict.findEntry("coarseGraining", Foam::keyType::LITERAL);
    if (!e) return 1;
    double value = std::numeric_limits<double>::quiet_NaN();
    Foam::OStringStream os;
    if (!e->isDict())
    {
        Foam::ITstream& is = e->stream();
        if (is.size() == 1 && is[0].isNumber()) value = is[0].number();
        forAll(is, i) os << (i ? " " : "") << is[i];
    }
    return checkedCoarseGraining(value, e->isDict() ? "a dictionary" : os.str(), file);
}

} // namespace spoutlab
