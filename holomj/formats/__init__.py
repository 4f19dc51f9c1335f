"""Output formats in memory: ``objects.json`` records, the navigation map, scene summaries, and
the scene as GLB, USD and URDF (``holomj export``).

Writing them into an output folder is the jobs layer's (:mod:`holomj.jobs.folder`).
"""
