#include <nitsche_contact/model_registry.h>

#include <algorithm>
#include <map>

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
    } // namespace

    bool
    add(const Entry &entry)
    {
      registry()[entry.name] = entry;
      return true;
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
