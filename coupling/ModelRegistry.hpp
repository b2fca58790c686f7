#pragma once
// The run-time selection of a model family (drag laws, void-fraction models,
// heat-transfer correlations), docs/DESIGN.md §5.
//
// Each family's base class owns one registry; a model joins it from its own
// .cpp with
//     const Registration<DragModel, Gidaspow> registered("Gidaspow");
// so adding a model touches no other file. The registration objects run while
// the program starts; coupling/ is built as an object library so that no
// model's translation unit is left out of the link (an archive would drop the
// files nothing else refers to, and their models with them).
//
// Names are kept sorted, because the order in which translation units start
// is not defined; the lists in errors and in `spoutFoam -listModels` are
// therefore the same on every build.

#include "InputError.hpp"
#include "Parameters.hpp"

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace spoutlab
{

template <class Base>
class ModelRegistry
{
public:
    using Factory = std::unique_ptr<Base> (*)(const Parameters&);

    // key: the dictionary entry that selects a model of this family, e.g. "dragModel"
    explicit ModelRegistry(std::string key) : key_(std::move(key)) {}

    const std::string& key() const { return key_; }

    // A second model under one name is a programming error, found at start-up.
    void add(const std::string& name, Factory factory)
    {
        if (!factories_.emplace(name, factory).second)
        {
            throw std::logic_error(key_ + " '" + name + "' registered twice");
        }
    }

    std::vector<std::string> names() const
    {
        std::vector<std::string> out;
        for (const auto& entry : factories_) out.push_back(entry.first);
        return out;
    }

    // The names as errors and listings print them: "Beetstra, DiFelice, Gidaspow".
    std::string namesList() const
    {
        std::string list;
        for (const auto& entry : factories_) list += (list.empty() ? "" : ", ") + entry.first;
        return list;
    }

    // The one error for a name no model registered under, naming the
    // dictionary that holds the key.
    void require(const std::string& name, const std::string& dictionary) const
    {
        if (factories_.count(name) != 0) return;
        throw InputError(dictionary + ": key '" + key_ + "' expected one of " + namesList() + ", got '" + name
                         + "'");
    }

    // props: the model's settings, by convention the sub-dictionary <name>Props
    // of the dictionary that selects it, which is where a bad name is reported.
    std::unique_ptr<Base> create(const std::string& name, const Parameters& props) const
    {
        require(name, selectingDictionary(props.context(), name));
        return factories_.at(name)(props);
    }

private:
    static std::string selectingDictionary(const std::string& settings, const std::string& name)
    {
        const std::string suffix = "/" + name + "Props";
        const bool nested = settings.size() > suffix.size()
                            && settings.compare(settings.size() - suffix.size(), suffix.size(), suffix) == 0;
        return nested ? settings.substr(0, settings.size() - suffix.size()) : settings;
    }

    std::string key_;
    std::map<std::string, Factory> factories_; // sorted by name
};

// A static object of this type in a model's .cpp registers the model with its
// family: Base::registry() must return the family's ModelRegistry<Base>.
template <class Base, class Model>
class Registration
{
public:
    explicit Registration(const char* name) { Base::registry().add(name, &make); }

private:
    static std::unique_ptr<Base> make(const Parameters& props)
    {
        return std::unique_ptr<Base>(new Model(props));
    }
};

} // namespace spoutlab
