# The layers (docs/architecture.md): every directory of the sources and what its files may include,
# the one table behind the include check (check_includes.cmake) and the layer table of
# docs/architecture.md (check_includes.cmake -DPRINT=ON prints it; architecture.readme checks that page holds
# it).
#
#   layers            the directories, lowest first; "app" is app/'s own files (the command line),
#                     not its subdirectories
#   uses_<dir>        the project's directories its files may include from (prefixes)
#   outside_<dir>     the outside headers it may include: gl (GL, GLAD, GLFW, EGL, KHR, OSMesa) and
#                     imgui (Dear ImGui and its backends); none: neither
#   about_<dir>       what the layer is, for docs/architecture.md
set(layers pipeline io course app/text app/views app/core app/fonts app/export app/context app/gl app/render app/ui
           app/course app/lessons app bench app/web)

set(uses_pipeline pipeline/)
set(outside_pipeline none)
set(about_pipeline "the five stages, the scene, meshes and primitives: pure math (no files, no GL)")

set(uses_io pipeline/ io/)
set(outside_io none)
set(about_io "file formats and their limits: scenes, OBJ meshes, the dump")

set(uses_course pipeline/ io/ course/)
set(outside_course none)
set(about_course "the course's mathematics: exercise sheets, exact solutions, grading, mistake models")

set(uses_app/text pipeline/ app/text/)
set(outside_app/text none)
set(about_app/text "the catalogue: every text a user reads, in English and German")

set(uses_app/views pipeline/ app/text/ app/views/)
set(outside_app/views none)
set(about_app/views "each view described once, as a display list")

set(uses_app/core pipeline/ io/ app/text/ app/views/ app/core/)
set(outside_app/core none)
set(about_app/core "the viewer's state without GL: document, files, autosave, address, picking, panel texts, the pipeline's worker")

set(uses_app/fonts pipeline/ app/text/ app/views/ app/fonts/)
set(outside_app/fonts imgui)
set(about_app/fonts "label metrics and glyphs (Dear ImGui's font atlas, no GL)")

set(uses_app/export pipeline/ app/text/ app/views/ app/fonts/ app/export/)
set(outside_app/export none)
set(about_app/export "the SVG backend, image comparison, the CPU raster oracle")

set(uses_app/context pipeline/ app/context/)
set(outside_app/context gl)
set(about_app/context "OpenGL contexts, one file per backend behind one interface")

set(uses_app/gl pipeline/ app/views/ app/gl/)
set(outside_app/gl gl)
set(about_app/gl "shaders, render targets, texture read-back")

set(uses_app/render pipeline/ app/text/ app/core/ app/views/ app/fonts/ app/export/ app/context/ app/gl/ app/render/)
set(outside_app/render gl imgui)
set(about_app/render "the GL backend of the display lists, the views' images and their render thread")

set(uses_app/ui pipeline/ io/ app/text/ app/core/ app/views/ app/fonts/ app/export/ app/context/ app/gl/ app/render/ app/ui/)
set(outside_app/ui gl imgui)
set(about_app/ui "the viewer: the frame, its session, menus, panels, the views' panes")

set(uses_app/course pipeline/ io/ course/ app/text/ app/views/ app/fonts/ app/export/ app/context/ app/gl/ app/render/ app/course/)
set(outside_app/course none)
set(about_app/course "the commands vplab exercise and vplab grade on course/: sheets, reports, pictures graded")

set(uses_app/lessons pipeline/ io/ app/text/ app/core/ app/views/ app/fonts/ app/export/ app/context/ app/gl/ app/render/ app/lessons/)
set(outside_app/lessons none)
set(about_app/lessons "vplab render --lesson: a lesson's steps as pictures with captions, its index, its animation")

set(uses_app pipeline/ io/ course/ app/ bench/)
set(outside_app none)
set(about_app "the command line (app/cli.cpp, app/main.cpp)")

set(uses_bench pipeline/ io/ app/text/ app/core/ app/views/ app/fonts/ app/export/ app/context/ app/gl/ app/render/ app/ui/ bench/)
set(outside_bench gl imgui)
set(about_bench "vplab bench and the benchmark workloads")

set(uses_app/web pipeline/ io/ app/)
set(outside_app/web gl imgui)
set(about_app/web "the page: the browser's frame loop and services")
