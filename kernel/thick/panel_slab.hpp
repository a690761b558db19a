#pragma once
// The slab of one thick panel at the flat state: the panel's flat polygon swept in z from
// `bottom` to `top` (pattern units, top > bottom). How the heights are chosen per hinge
// placement is panel_slabs' business (thick_slabs.hpp); this header only names the type so
// that the geometry checks (slab_interference.hpp, stacking_order.hpp) need not include the
// report.
namespace rigidfold {

struct PanelSlab {
  double bottom = 0.0, top = 0.0;  // pattern units, top > bottom
};

}  // namespace rigidfold
