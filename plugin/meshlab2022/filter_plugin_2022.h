// MeshLab 2022.02-and-later adapter (FilterPlugin): the 2022.02 and 2025.07 GUIs and pymeshlab
// (2025.07, double scalars). Entry points and error protocol only; the filter itself is
// plugin/shared/vertex_removal_filter. One binary per MeshLab version and scalar: the host
// refuses a plugin whose version or precision differ from its own.
#pragma once

#include <common/plugins/interfaces/filter_plugin.h>

class FilterVertexRemovalPlugin : public QObject, public FilterPlugin {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
  Q_INTERFACES(FilterPlugin)

 public:
  enum { FP_VERTEX_REMOVAL };

  FilterVertexRemovalPlugin();

  QString pluginName() const override;
  QString filterName(ActionIDType filter) const override;
  QString pythonFilterName(ActionIDType filter) const override;
  QString filterInfo(ActionIDType filter) const override;
  FilterClass getClass(const QAction*) const override;
  int getPreConditions(const QAction*) const override;
  int postCondition(const QAction*) const override;
  FilterArity filterArity(const QAction*) const override { return SINGLE_MESH; }
  RichParameterList initParameterList(const QAction*, const MeshModel& m) override;
  // 2022+'s protocol: failures are thrown as MLException (the GUI shows its dialog, pymeshlab
  // raises PyMeshLabException); the result map becomes pymeshlab's returned dict.
  std::map<std::string, QVariant> applyFilter(const QAction* filter, const RichParameterList& par,
                                              MeshDocument& md, unsigned int& postConditionMask,
                                              vcg::CallBackPos* cb) override;
};
