// MeshLab filter "Simplification: Vertex Removal Decimation": parameters in, one call to the
// core per level, a log line out. All geometry lives in core/.
#pragma once

#include <common/interfaces.h>

#include <functional>

namespace vrs_plugin {
struct FilterSettings;
}

class FilterVertexRemovalPlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

 public:
  enum { FP_VERTEX_REMOVAL };

  FilterVertexRemovalPlugin();

  QString pluginName() const override;
  QString filterName(FilterIDType filter) const override;
  QString filterInfo(FilterIDType filter) const override;
  FilterClass getClass(QAction*) override;
  int getPreConditions(QAction*) const override;
  int postCondition(QAction*) const override;
  FILTER_ARITY filterArity(QAction*) const override { return SINGLE_MESH; }
  void initParameterSet(QAction*, MeshModel& m, RichParameterList& par) override;
  bool applyFilter(QAction* filter, MeshDocument& md, const RichParameterList& par,
                   vcg::CallBackPos* cb) override;

 private:
  bool apply_checked(MeshDocument& md, const RichParameterList& par, vcg::CallBackPos* cb);
  // Simplifies one layer in place; "" or the error (the layer is then unchanged).
  QString simplify_layer(MeshModel& m, const vrs_plugin::FilterSettings& s, int level,
                         const std::function<bool(float)>& progress);
};
