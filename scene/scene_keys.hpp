// One declaration function per module, each in scene/scene_keys_<module>.cpp. scene_schema()
// (scene/scene_schema.cpp) calls every one of them: add a module's function here and there.
#pragma once

#include "scene/scene_schema.hpp"

namespace valsalva::scene {

void declare_run_keys(Schema& schema);        // scene/scene_keys_run.cpp
void declare_mesh_keys(Schema& schema);       // scene/scene_keys_mesh.cpp
void declare_partition_keys(Schema& schema);  // scene/scene_keys_partition.cpp
void declare_flow_keys(Schema& schema);       // scene/scene_keys_flow.cpp
void declare_rheology_keys(Schema& schema);   // scene/scene_keys_rheology.cpp
void declare_forcing_keys(Schema& schema);    // scene/scene_keys_forcing.cpp
void declare_boundary_keys(Schema& schema);   // scene/scene_keys_boundary.cpp
void declare_les_keys(Schema& schema);        // scene/scene_keys_les.cpp
void declare_analysis_keys(Schema& schema);   // scene/scene_keys_analysis.cpp
void declare_section_keys(Schema& schema);    // scene/scene_keys_sections.cpp
void declare_structure_keys(Schema& schema);  // scene/scene_keys_structure.cpp
void declare_valve_keys(Schema& schema);      // scene/scene_keys_valve.cpp

}  // namespace valsalva::scene
