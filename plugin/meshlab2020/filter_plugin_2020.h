// MeshLab 2020.09 adapter (MeshFilterInterface; meshlabserver and the 2020.09 GUI): entry
// points and error protocol only. The filter itself is plugin/shared/vertex_removal_filter.
#pragma once

#include <common/interfaces.h>

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
  // 2020.09's protocol: false with errorMessage set; nothing may be thrown.
  bool applyFilter(QAction* filter, MeshDocument& md, const RichParameterList& par,
                   vcg::CallBackPos* cb) override;
};
