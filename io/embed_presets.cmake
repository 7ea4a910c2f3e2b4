# Writes presets_data.h: every presets/*.json as a raw string literal, so the program carries
# its named scenes. Run at build time when a preset changes.
file(GLOB files "${PRESET_DIR}/*.json")
list(SORT files)
set(out "// Generated from presets/*.json by io/embed_presets.cmake; do not edit.\n#pragma once\n#include \"io/presets.h\"\nnamespace vibro {\ninline const PresetText kPresetData[] = {\n")
foreach(f ${files})
  get_filename_component(name ${f} NAME_WE)
  file(READ ${f} text)
  string(APPEND out "  {\"${name}\", R\"vibro_preset(${text})vibro_preset\"},\n")
endforeach()
string(APPEND out "};\n}  // namespace vibro\n")
file(WRITE "${OUT}.tmp" "${out}")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different "${OUT}.tmp" "${OUT}")
