#pragma once

namespace odelab {

// What ERP and CFM mean physically (ODE manual, "Joint error and the error
// reduction parameter" / "Soft constraint and constraint force mixing"): a
// constraint with ERP and CFM at step h behaves as a spring of stiffness kp
// and a damper of coefficient kd, where
//   ERP = h kp / (h kp + kd),   CFM = 1 / (h kp + kd).
// CFM = 0 is a rigid constraint (kp, kd infinite).
struct SpringDamper {
  double kp;  // N/m (per unit of constraint error)
  double kd;  // N s/m
  bool rigid;
};

SpringDamper springDamperOf(double erp, double cfm, double step);

// The ERP and CFM that give the same spring and damper at another step.
struct ErpCfm {
  double erp;
  double cfm;
};
ErpCfm erpCfmFor(const SpringDamper& spring, double step);

}  // namespace odelab
