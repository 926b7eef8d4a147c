// The list of models. A model registers itself in its own .cc file with
//
//   NITSCHE_CONTACT_REGISTER_MODEL(MyModel, "name", "one-line description")
//
// where MyModel derives from ContactModel, has a static
// declare_parameters(ParameterHandler &) for its own subsection and a
// constructor MyModel(const CommonParameters &, ParameterHandler &,
// MPI_Comm). The 'Model' entry, the --help list and the error for an
// unknown model come from this list; nothing else names a model.
#ifndef nitsche_contact_model_registry_h
#define nitsche_contact_model_registry_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <nitsche_contact/model.h>
#include <nitsche_contact/parameters.h>

#include <memory>
#include <string>
#include <vector>

namespace NitscheContact
{
  namespace ModelRegistry
  {
    using DeclareFunction = void (*)(dealii::ParameterHandler &);
    using CreateFunction  = std::unique_ptr<ContactModel> (*)(
      const CommonParameters &, dealii::ParameterHandler &, MPI_Comm);

    struct Entry
    {
      std::string     name;
      std::string     description;
      DeclareFunction declare;
      CreateFunction  create;
    };

    /// The model of a parameter file that does not set 'Model'.
    inline constexpr const char *default_model = "elasticity";

    /// Add a model (at static initialisation, by the macro below); returns
    /// true so that the macro can keep the result in a constant. A second
    /// model of the same name is kept aside for check().
    bool
    add(const Entry &entry);

    /// std::logic_error naming the model unless every name is registered
    /// once and the default model is among them; main() calls it first.
    void
    check();

    /// The registered models, sorted by name.
    std::vector<Entry>
    entries();

    /// "name1|name2|..." for Patterns::Selection.
    std::string
    selection_pattern();

    /// Declare every model's subsection, so that one schema covers all
    /// .prm files.
    void
    declare_parameters(dealii::ParameterHandler &prm);

    /// Construct the model selected by common.model; InputError for an
    /// unknown name.
    std::unique_ptr<ContactModel>
    create(const CommonParameters   &common,
           dealii::ParameterHandler &prm,
           MPI_Comm                  comm);
  } // namespace ModelRegistry
} // namespace NitscheContact

#define NITSCHE_CONTACT_REGISTER_MODEL(Class, name, description)          \
  namespace                                                               \
  {                                                                       \
    const bool model_is_registered = NitscheContact::ModelRegistry::add(   \
      {name,                                                              \
       description,                                                       \
       &Class::declare_parameters,                                        \
       [](const NitscheContact::CommonParameters &common,                 \
          dealii::ParameterHandler               &prm,                    \
          MPI_Comm comm) -> std::unique_ptr<NitscheContact::ContactModel> { \
         return std::make_unique<Class>(common, prm, comm);               \
       }});                                                               \
  }

#endif
