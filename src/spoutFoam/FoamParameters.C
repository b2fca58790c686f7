/*---------------------------------------------------------------------------*\
    SpoutLab: couplingProperties entries as Parameters.
\*---------------------------------------------------------------------------*/
#include "FoamParameters.H"

#include "OStringStream.H"

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


} // namespace spoutlab
