#include <nitsche_contact/model_factory.h>
#include <nitsche_contact/models/elasticity.h>
#include <nitsche_contact/models/kirchhoff.h>
#include <nitsche_contact/models/mindlin.h>

namespace NitscheContact
{
  void
  declare_model_parameters(dealii::ParameterHandler &prm)
  {
    ElasticityModel::declare_parameters(prm);
    MindlinModel::declare_parameters(prm);
    KirchhoffModel::declare_parameters(prm);
  }

  std::vector<std::string>
  available_models()
  {
    return {"elasticity", "mindlin", "kirchhoff"};
  }

  std::unique_ptr<ContactModel>
  create_model(const CommonParameters   &common,
               dealii::ParameterHandler &prm,
               MPI_Comm                  comm)
  {
    if (common.model == "elasticity")
      return std::make_unique<ElasticityModel>(common, prm, comm);
    if (common.model == "mindlin")
      return std::make_unique<MindlinModel>(common, prm, comm);
    if (common.model == "kirchhoff")
      return std::make_unique<KirchhoffModel>(common, prm, comm);
    throw InputError("invalid value '" + common.model +
                     "' for parameter 'Model': allowed are 'elasticity', "
                     "'mindlin', 'kirchhoff'");
  }
} // namespace NitscheContact
