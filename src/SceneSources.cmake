# The scene floor's sources (absolute paths): the base floor core/, the
# shadow geometry geometry/, the technique catalog with each technique's
# options table (techniques/<Name>Options.cpp, map/options/), and the scene
# loaders scene/. Nothing here includes gl/, render/ or a technique's GL
# half (tests/code/floors.py checks it), so these link without OpenGL:
# src/CMakeLists.txt's shadowlab_scene and the fuzz targets use this list.
set(_scene_dir ${CMAKE_CURRENT_LIST_DIR})
file(GLOB _technique_options CONFIGURE_DEPENDS ${_scene_dir}/techniques/*Options.cpp ${_scene_dir}/techniques/*/options/*.cpp)
set(SHADOWLAB_SCENE_SOURCES
  ${_technique_options}
  ${_scene_dir}/techniques/Catalog.cpp
  ${_scene_dir}/core/Base64.cpp
  ${_scene_dir}/core/FileWrite.cpp
  ${_scene_dir}/core/Image.cpp
  ${_scene_dir}/core/Options.cpp
  ${_scene_dir}/core/Adjacency.cpp
  ${_scene_dir}/core/AtlasLayout.cpp
  ${_scene_dir}/core/MeshLevels.cpp
  ${_scene_dir}/core/EdgeCollapser.cpp
  ${_scene_dir}/core/EdgeCollapse.cpp
  ${_scene_dir}/core/TriangleOrder.cpp
  ${_scene_dir}/core/ScreenRect.cpp
  ${_scene_dir}/core/Text.cpp
  ${_scene_dir}/geometry/LightCamera.cpp
  ${_scene_dir}/geometry/LightFitParts.cpp
  ${_scene_dir}/geometry/Cascades.cpp
  ${_scene_dir}/geometry/LightTiles.cpp
  ${_scene_dir}/geometry/MeshTwins.cpp
  ${_scene_dir}/geometry/Plane.cpp
  ${_scene_dir}/geometry/ShadowRegion.cpp
  ${_scene_dir}/scene/Scene.cpp
  ${_scene_dir}/scene/Paths.cpp
  ${_scene_dir}/scene/Shapes.cpp
  ${_scene_dir}/scene/MeshFile.cpp
  ${_scene_dir}/scene/GltfFile.cpp
  ${_scene_dir}/scene/GltfImporter.cpp
  ${_scene_dir}/scene/GltfData.cpp
  ${_scene_dir}/scene/GltfSchema.cpp
  ${_scene_dir}/scene/GltfScene.cpp
  ${_scene_dir}/scene/GltfIncludes.cpp
  ${_scene_dir}/scene/GltfExport.cpp
  ${_scene_dir}/scene/SceneJson.cpp
  ${_scene_dir}/scene/CameraFile.cpp
  ${_scene_dir}/scene/LightFile.cpp
  ${_scene_dir}/scene/LightGridFile.cpp
  ${_scene_dir}/scene/ShadowAtlasFile.cpp
  ${_scene_dir}/scene/MaterialFile.cpp
  ${_scene_dir}/scene/ShapeFile.cpp
  ${_scene_dir}/scene/NodeFile.cpp
  ${_scene_dir}/scene/SceneFile.cpp
  ${_scene_dir}/scene/Overrides.cpp
)
