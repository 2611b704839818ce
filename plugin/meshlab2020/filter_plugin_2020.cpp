#include "filter_plugin_2020.h"

#include "filter_parameters.h"
#include "vertex_removal_filter.h"

FilterVertexRemovalPlugin::FilterVertexRemovalPlugin() {
  typeList << FP_VERTEX_REMOVAL;
  for (FilterIDType t : types())
    actionList << new QAction(filterName(t), this);
}

QString FilterVertexRemovalPlugin::pluginName() const {
  return "FilterVertexRemoval";
}

QString FilterVertexRemovalPlugin::filterName(FilterIDType) const {
  return vrs_plugin::filter_name();
}

QString FilterVertexRemovalPlugin::filterInfo(FilterIDType) const {
  return vrs_plugin::filter_info();
}

MeshFilterInterface::FilterClass FilterVertexRemovalPlugin::getClass(QAction*) {
  return MeshFilterInterface::Remeshing;
}

int FilterVertexRemovalPlugin::getPreConditions(QAction*) const {
  return MeshModel::MM_FACENUMBER;
}

int FilterVertexRemovalPlugin::postCondition(QAction*) const {
  return MeshModel::MM_GEOMETRY_AND_TOPOLOGY_CHANGE;
}

void FilterVertexRemovalPlugin::initParameterSet(QAction*, MeshModel& m, RichParameterList& par) {
  vrs_plugin::declare_parameters(m, par);
}

bool FilterVertexRemovalPlugin::applyFilter(QAction*, MeshDocument& md,
                                            const RichParameterList& par, vcg::CallBackPos* cb) {
  vrs_plugin::Host host;
  host.log = [this](GLLogStream::Levels level, const QString& text) {
    Log(level, "%s", qUtf8Printable(text));
  };
  host.progress = cb;
  vrs_plugin::Outcome out = vrs_plugin::apply_vertex_removal(md, par, host);
  if (out.ok) return true;
  errorMessage = out.error;
  // meshlabserver prints the log but not the error message: say it in both.
  Log(GLLogStream::WARNING, "%s", qUtf8Printable(errorMessage));
  return false;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterVertexRemovalPlugin)
