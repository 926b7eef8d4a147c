#include <nitsche_contact/model_registry.h>

#include <algorithm>
#include <map>
#include <stdexcept>

namespace NitscheContact
{
  namespace ModelRegistry
  {
    namespace
    {
      /// (a function's static: filled during static initialisation)
      std::map<std::string, Entry> &
      registry()
      {
        static std::map<std::string, Entry> models;
        return models;
      }

      /// names registered more than once
      std::vector<std::string> &
      duplicates()
      {
        static std::vector<std::string> names;
        return names;
      }
    } // namespace

    bool
    add(const Entry &entry)
    {
      if (!registry().emplace(entry.name, entry).second)
        duplicates().push_back(entry.name);
      return true;
    }

    void
    check()
    {
      if (!duplicates().empty())
        throw std::logic_error("two models are registered with the name '" +
                               duplicates().front() +
                               "'; each NITSCHE_CONTACT_REGISTER_MODEL needs "
                               "a name of its own");
      if (registry().count(default_model) == 0)
        throw std::logic_error(std::string("the default model '") +
                               default_model + "' is not registered");
    }

    std::vector<Entry>
    entries()
    {
      std::vector<Entry> list;
      for (const auto &m : registry())
        list.push_back(m.second);
      return list;
    }

    std::string
    selection_pattern()
    {
      std::string names;
      for (const auto &m : registry())
        names += (names.empty() ? "" : "|") + m.first;
      return names;
    }

    void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      for (const auto &m : registry())
        m.second.declare(prm);
    }

    std::unique_ptr<ContactModel>
    create(const CommonParameters   &common,
           dealii::ParameterHandler &prm,
           MPI_Comm                  comm)
    {
      const auto m = registry().find(common.model);
      if (m == registry().end())
        {
          std::string allowed;
          for (const auto &e : registry())
            allowed += (allowed.empty() ? "'" : ", '") + e.first + "'";
          bad_value("Model", common.model, "allowed are " + allowed);
        }
      return m->second.create(common, prm, comm);
    }
  } // namespace ModelRegistry
} // namespace NitscheContact
