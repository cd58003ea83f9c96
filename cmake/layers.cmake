# The layers (docs/architecture.md): every directory of the sources, what its files may include and
# so what its library links. The one table behind
#   - the build: cmake/Layers.cmake makes each directory's library link exactly the layers of its row,
#     and checks every include against the table before anything compiles (check_includes.cmake), so a
#     forbidden include fails the build;
#   - the test architecture.includes (the same check, on the sources as they are when it runs);
#   - docs/architecture.md's layer table (check_includes.cmake -DPRINT=ON prints it; architecture.readme
#     checks that the page holds it).
#
#   layers            the directories, lowest first; a row names only layers before it (no circle)
#   uses_<dir>        the project's directories its files include from, its own included: exactly those
#                     (a row that allows a layer none of its files includes fails the check too)
#   outside_<dir>     the outside headers it may include: gl (GL, GLAD, GLFW, EGL, KHR, OSMesa) and
#                     imgui (Dear ImGui and its backends); none: neither
#   about_<dir>       what the layer holds, for docs/architecture.md
set(layers base pipeline io course app/text app/views app/workers app/document app/inspect app/lessons app/practice app/session app/fonts
           app/export app/context app/gl app/render app/ui app/course_kit bench app/commands app/web)

set(uses_base base/)
set(outside_base none)
set(about_base "what every layer shares: the error users read, the two languages, a table of names per enum")

set(uses_pipeline base/ pipeline/)
set(outside_pipeline none)
set(about_pipeline "the five stages, the scene, meshes and primitives: pure math (no files, no GL)")

set(uses_io base/ pipeline/ io/)
set(outside_io none)
set(about_io "file formats and their limits: scenes, OBJ meshes, the dump")

set(uses_course base/ pipeline/ io/ course/)
set(outside_course none)
set(about_course "the course's mathematics: exercise sheets, exact solutions, grading, mistake models, Moodle's files")

set(uses_app/text base/ app/text/)
set(outside_app/text none)
set(about_app/text "the catalogue: every text a user reads, in English and German")

set(uses_app/views base/ pipeline/ app/text/ app/views/)
set(outside_app/views none)
set(about_app/views "each view described once, as a display list")

set(uses_app/workers pipeline/ app/workers/)
set(outside_app/workers none)
set(about_app/workers "threads where the latest request wins: the skeleton, their low priority, the pipeline's worker")

set(uses_app/document base/ pipeline/ io/ course/ app/text/ app/views/ app/document/)
set(outside_app/document none)
set(about_app/document "the scene being edited and its files: undo, loading, atomic saving, autosave and recovery, preferences, the installed assets, the page's address")

set(uses_app/inspect base/ pipeline/ app/text/ app/views/ app/inspect/)
set(outside_app/inspect none)
set(about_app/inspect "what the panels pick and print without GL: handles and vertices under the pointer, the camera's, matrices' and vanishing points' texts")

set(uses_app/lessons base/ pipeline/ io/ app/views/ app/document/ app/inspect/ app/lessons/)
set(outside_app/lessons none)
set(about_app/lessons "a lesson without GL: its file, its steps, how it frames the views, its marks, its player and the camera's transitions")

set(uses_app/practice base/ pipeline/ io/ course/ app/views/ app/practice/)
set(outside_app/practice none)
set(about_app/practice "an exercise practised beside the views: its tasks and the student's fields, Check through course/'s grader, the student's numbers as marks in the views")

set(uses_app/session base/ pipeline/ io/ app/text/ app/views/ app/document/ app/inspect/ app/lessons/ app/practice/ app/session/)
set(outside_app/session none)
set(about_app/session "the viewer's state in parts and the document's life without ImGui: open, save, autosave and recovery, links, lessons opened, the questions the dialogs ask")

set(uses_app/fonts base/ app/views/ app/fonts/)
set(outside_app/fonts imgui)
set(about_app/fonts "label metrics and glyphs (Dear ImGui's font atlas, no GL)")

set(uses_app/export base/ pipeline/ app/views/ app/fonts/ app/export/)
set(outside_app/export none)
set(about_app/export "the SVG backend, image comparison, the CPU raster oracle, animations")

set(uses_app/context base/ app/context/)
set(outside_app/context gl)
set(about_app/context "OpenGL contexts, one file per backend behind one interface")

set(uses_app/gl base/ pipeline/ app/views/ app/gl/)
set(outside_app/gl gl)
set(about_app/gl "shaders, render targets, texture read-back")

set(uses_app/render base/ pipeline/ app/views/ app/workers/ app/fonts/ app/export/ app/context/ app/gl/ app/render/)
set(outside_app/render imgui)
set(about_app/render "the GL backend of the display lists, the views' images and their render thread")

set(uses_app/ui base/ pipeline/ io/ course/ app/text/ app/views/ app/workers/ app/document/ app/inspect/ app/lessons/ app/practice/ app/session/ app/fonts/
    app/export/ app/context/ app/gl/ app/render/ app/ui/)
set(outside_app/ui gl imgui)
set(about_app/ui "the viewer: the frame, its session, menus, panels, the views' panes")

set(uses_app/course_kit base/ pipeline/ io/ course/ app/views/ app/export/ app/render/ app/course_kit/)
set(outside_app/course_kit none)
set(about_app/course_kit "the course staff's kit on course/: sheets with their figures, a class's exercises and grades, reports, pictures graded")

set(uses_bench base/ pipeline/ bench/)
set(outside_bench none)
set(about_bench "the benchmark workloads (`vplab bench` is a command) and the Google Benchmark target")

set(uses_app/commands base/ io/ course/ app/text/ app/views/ app/document/ app/lessons/ app/practice/ app/fonts/ app/export/ app/render/
    app/ui/ app/course_kit/ bench/ app/commands/)
set(outside_app/commands none)
set(about_app/commands "the command line: every subcommand (the window, render, dump, bench, exercise, grade, a lesson's pictures) and main")

set(uses_app/web base/ io/ course/ app/document/ app/session/ app/context/ app/gl/ app/ui/ app/web/)
set(outside_app/web gl imgui)
set(about_app/web "the page: the browser's frame loop and services")
