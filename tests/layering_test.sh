#!/usr/bin/env bash
# Enforces architecture.md §2: each layer includes only layers under it, and nothing below editor/
# includes Qt. Prints every offending include and exits 1 if there is one. scene may use plugins
# (which sit on util only) for the registry's list of BRDF names.
set -u
root=${1:-.}
cd "$root" || exit 2
status=0
check() { # folder, allowed include prefixes (regex alternation)
    local dir=$1 allowed=$2
    [ -d "$dir" ] || return 0
    while IFS= read -r line; do
        file=${line%%:*}
        inc=$(sed -E 's/.*#include *"([^"]+)".*/\1/' <<< "${line#*:}")
        top=${inc%%/*}
        [ "$top" = "$inc" ] && continue # same-folder include without a layer prefix
        [[ "$inc" =~ \.(h|hpp)$ ]] || continue # GLSL includes inside shader strings
        if ! [[ "$top" =~ ^($allowed)$ ]]; then
            echo "layering: $file includes \"$inc\" ($dir may use only: $allowed)"
            status=1
        fi
    done < <(grep -rnE '^ *#include *"' "$dir" --include='*.h' --include='*.cpp' | sed -E 's/^([^:]+):[0-9]+:/\1:/')
}
check renderer/util 'util'
check renderer/wavelet 'wavelet|util'
check renderer/scene 'scene|plugins|util'
check renderer/vk 'vk|util'
check plugins 'plugins|util'
check renderer/render 'render|scene|wavelet|vk|plugins|util'
# Inside render/ (its CMakeLists names each folder's job): lights and sampling never reach up into
# the tracers, the reference tracer never into the GPU one, only gpu/, session/ (the device limits)
# and testing/ touch Vulkan, and nothing in production includes testing/.
check_render() { # folder, forbidden include prefixes (regex alternation)
    local dir=renderer/render/$1 forbidden=$2
    while IFS= read -r line; do
        file=${line%%:*}
        inc=$(sed -E 's/.*#include *"([^"]+)".*/\1/' <<< "${line#*:}")
        case "$file" in *_test.cpp) [[ "$inc" =~ ^render/testing/ ]] && continue ;; esac
        if [[ "$inc" =~ ^($forbidden) ]]; then
            echo "layering: $file includes \"$inc\" (render/$1 may not use: $forbidden)"
            status=1
        fi
    done < <(grep -nE '^ *#include *"' "$dir"/*.h "$dir"/*.cpp 2>/dev/null | sed -E 's/^([^:]+):[0-9]+:/\1:/')
}
check_render lights 'render/(session|sampling|reference|gpu|testing)/|vk/'
check_render sampling 'render/(reference|gpu|testing)/|vk/'
check_render sampling/product 'render/(session|reference|gpu|testing)/|vk/'
check_render reference 'render/(gpu|testing)/|vk/'
check_render session 'render/testing/|vk/'
check_render gpu 'render/testing/'
# relight (the wavelet relighting preview): scene (with its CPU BVH), wavelet and the BRDF plugins;
# never render/ (which links Vulkan) and never vk.
check renderer/relight 'relight|scene|wavelet|plugins|util'
check renderer/cli 'cli|relight|render|scene|wavelet|vk|plugins|util'
check editor 'app|viewport|panels|commands|scripting|lightmix|editor|render|relight|scene|util'
qt=$(grep -rlnE '#include *<Q[A-Za-z]|#include *<Qt' renderer plugins 2>/dev/null)
if [ -n "$qt" ]; then
    echo "layering: Qt included below editor/: $qt"
    status=1
fi
# No code outside plugins/ names a BRDF (issue 11): renderer/, editor/ and shaders/ read a plugin's
# traits (plugins/brdf.h), never its name. The names are what the plugins' name() returns;
# comments, tests and their support (render/testing/, *_test_support.h) and scene data may name one.
# A name counts where no letter precedes it: `ggxEval` and "ward" do, camForward does not.
for brdf in $(grep -hoE 'name\(\) const override \{ return "[^"]+"' \
                  $(ls plugins/*.cpp 2>/dev/null | grep -v '_test\.cpp$') 2>/dev/null | sed -E 's/.*"([^"]+)"/\1/' | sort -u); do
    while IFS= read -r hit; do
        code=${hit#*:*:}
        code=${code%%//*}
        if grep -qiE -- "(^|[^[:alpha:]])$brdf" <<< "$code"; then
            echo "layering: ${hit%%:*} names the BRDF '$brdf' outside plugins/ (use its traits): ${hit#*:}"
            status=1
        fi
    done < <(grep -rniE --include='*.h' --include='*.cpp' --include='*.glsl' --include='*.comp' -- "(^|[^[:alpha:]])$brdf" \
                 renderer editor shaders 2>/dev/null | grep -vE '^[^:]*(_test\.cpp|_test_support\.h|/testing/|/tests/)[^:]*:')
done
[ $status -eq 0 ] && echo "layering: ok"
exit $status
