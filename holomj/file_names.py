"""The one owner of the file and folder names holomj writes: output folders and asset libraries.

Every module that reads or writes an output folder or an asset library takes these names from
here; none spells them as literals.
"""

from __future__ import annotations

# an asset library: LIB/library.json and LIB/<folder>/asset.json
LIBRARY_INDEX = "library.json"
LIBRARY_META = "asset.json"
LIBRARY_BLOBS = ".blobs"  # content-addressed images, hard-linked into the asset folders
MATERIALS_INDEX = "materials.json"  # a material library's index

# an output folder (see holomj.jobs.folder for what each holds)
SCENE_XML = "scene.xml"
SCENE_JSON = "scene.json"
ASSETS_DIR = "assets"
OBJECTS_JSON = "objects.json"
NAVMAP_JSON = "navmap.json"
NAVMAP_PNG = "navmap.png"
ROBOT_JSON = "robot.json"
TASKS_JSON = "tasks.json"
IMPORT_REPORT = "import_report.json"
PLAN_JSON = "plan.json"
GENERATE_JSON = "generate.json"
GENERATE_LOG = "generate.log"
REPORT_JSON = "report.json"
POPULATE_REPORT = "populate_report.json"
RENDERS_DIR = "renders"
REPORT_HTML = "report.html"
