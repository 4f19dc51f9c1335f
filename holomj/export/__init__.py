"""Output formats in memory: ``objects.json`` records, the navigation map, scene summaries.

Writing them into an output folder is the jobs layer's (:mod:`holomj.jobs.folder`).
"""
