// The colours of the methods one figure shows.
//
// The paper's methods keep theirs in every figure: original vermillion, trunc blue, dtw bluish green, hampel
// reddish purple. The figure's other methods take the palette's remaining colours in the order given, so that
// no two share one while the palette lasts (8 colours, then it wraps around). An estimator's variants of
// the figure's methods, PREFIX_METHOD (e.g. openvins_trunc beside trunc) where at least two methods share
// PREFIX_, take their method's hue in a shade of their own: the first prefix darker, the second lighter.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "plots/image.h"

namespace vigil::plots {

class MethodColors {
 public:
  explicit MethodColors(const std::vector<std::string>& methods);
  // The method's colour; grey for a method not given to the constructor.
  Color Of(const std::string& method) const;

 private:
  std::map<std::string, Color> colors_;
};

}  // namespace vigil::plots
