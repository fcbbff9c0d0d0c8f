# Runs tests/data/lightmix.js in `wavelit --light-mix --script` on the default scene under the
# night lighting setup (window, lamp, spot: a copy of the resources in OUT_DIR) and checks it
# exits 0 and saved its images. Arguments: WAVELIT, SCRIPT, RESOURCES, OUT_DIR.
file(REMOVE_RECURSE ${OUT_DIR})
file(MAKE_DIRECTORY ${OUT_DIR}/envmaps)
file(COPY ${RESOURCES}/scenes ${RESOURCES}/meshes ${RESOURCES}/lighting DESTINATION ${OUT_DIR})
file(COPY ${RESOURCES}/envmaps/night.exr DESTINATION ${OUT_DIR}/envmaps)
file(READ ${OUT_DIR}/scenes/ring_on_ground.wlscene scene)
string(REPLACE "studio_soft.wllight" "night_emissive.wllight" scene "${scene}")
file(WRITE ${OUT_DIR}/scenes/night.wlscene "${scene}")
set(ENV{WAVELIT_SCRIPT_OUT} ${OUT_DIR})
execute_process(COMMAND ${WAVELIT} ${OUT_DIR}/scenes/night.wlscene --light-mix --script ${SCRIPT}
    --size 48x48 --sampler mis
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 360)
message("${out}${err}")
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "wavelit --light-mix --script exited with '${rc}'")
endif()
foreach(f lightmix_muted.exr lightmix_solo.exr)
    if(NOT EXISTS ${OUT_DIR}/${f})
        message(FATAL_ERROR "the script did not write ${OUT_DIR}/${f}")
    endif()
endforeach()
