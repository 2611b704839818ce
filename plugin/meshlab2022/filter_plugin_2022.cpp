#include "filter_plugin_2022.h"

#include "filter_parameters.h"
#include "vertex_removal_filter.h"

FilterVertexRemovalPlugin::FilterVertexRemovalPlugin() {
  typeList = {FP_VERTEX_REMOVAL};
  for (ActionIDType t : types())
    actionList.push_back(new QAction(filterName(t), this));
}

QString FilterVertexRemovalPlugin::pluginName() const {
  return "FilterVertexRemoval";
}

QString FilterVertexRemovalPlugin::filterName(ActionIDType) const {
  return vrs_plugin::filter_name();
}

QString FilterVertexRemovalPlugin::pythonFilterName(ActionIDType) const {
  return vrs_plugin::python_filter_name();
}

QString FilterVertexRemovalPlugin::filterInfo(ActionIDType) const {
  return vrs_plugin::filter_info();
}

FilterPlugin::FilterClass FilterVertexRemovalPlugin::getClass(const QAction*) const {
  return FilterPlugin::Remeshing;
}

int FilterVertexRemovalPlugin::getPreConditions(const QAction*) const {
  return MeshModel::MM_FACENUMBER;
}

int FilterVertexRemovalPlugin::postCondition(const QAction*) const {
  return MeshModel::MM_GEOMETRY_AND_TOPOLOGY_CHANGE;
}

RichParameterList FilterVertexRemovalPlugin::initParameterList(const QAction*, const MeshModel& m) {
  RichParameterList par;
  vrs_plugin::declare_parameters(m, par);
  return par;
}

std::map<std::string, QVariant>
FilterVertexRemovalPlugin::applyFilter(const QAction*, const RichParameterList& par,
                                       MeshDocument& md, unsigned int&, vcg::CallBackPos* cb) {
  vrs_plugin::Host host;
  host.log = [this](GLLogStream::Levels level, const QString& text) {
    log(level, text.toStdString());
  };
  host.progress = cb;
  vrs_plugin::Outcome out = vrs_plugin::apply_vertex_removal(md, par, host);
  if (!out.ok) throw MLException(out.error);
  return out.result;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterVertexRemovalPlugin)
