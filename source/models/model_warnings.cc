#include <nitsche_contact/model.h>
#include <nitsche_contact/parameters.h>

namespace NitscheContact
{
  std::vector<std::string>
  weak_penalty_warnings(const double gamma0)
  {
    // With r = gamma0 E / h_n far below the scale of the stresses, the
    // status follows sigma_n rather than the gap.
    if (!(gamma0 < 0.1))
      return {};
    return {"'Contact/Nitsche gamma0' = " + number_to_string(gamma0) +
            " < 0.1: the penalty r = gamma0 E / h_n is far below the scale "
            "of the stresses, so the contact condition is weakly enforced: "
            "points can carry pressure away from the obstacle, and the "
            "errors grow like 1/gamma0 (theta = -1 stays stable for any "
            "gamma0 > 0, theta = 1 and 0 need gamma0 above their bounds, "
            "doc/theory.md section 2.4)"};
  }
} // namespace NitscheContact
