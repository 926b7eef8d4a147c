// The list of models. Adding a model means: write a class derived from
// ContactModel with static declare_parameters(), add one line to each of the
// two functions in source/model_factory.cc, and add a .prm file.
#ifndef nitsche_contact_model_factory_h
#define nitsche_contact_model_factory_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <nitsche_contact/model.h>
#include <nitsche_contact/parameters.h>

#include <memory>
#include <string>
#include <vector>

namespace NitscheContact
{
  /// Declare the model-specific subsections of every model, so that one
  /// strict schema covers all .prm files.
  void
  declare_model_parameters(dealii::ParameterHandler &prm);

  /// Names accepted by "set Model".
  std::vector<std::string>
  available_models();

  /// Construct the model selected in the parameters; throws InputError for
  /// an unknown or unavailable model.
  std::unique_ptr<ContactModel>
  create_model(const CommonParameters   &common,
               dealii::ParameterHandler &prm,
               MPI_Comm                  comm);
} // namespace NitscheContact

#endif
