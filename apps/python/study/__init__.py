# SPDX-License-Identifier: BSD-3-Clause
"""Parameter studies of clearjoint models on Dask distributed.

A study file (JSON, ``docs/schema/study-v1.schema.json``) names a base model, the parameters to vary
(grids, element-wise lists, seeded random draws), ensemble members per point, the reduced outputs
kept per run and the store. ``python3 -m clearjoint.study run STUDY`` expands it into runs, calls
``clearjoint.simulate`` for each on a Dask cluster (a ``LocalCluster`` with one worker process per
core by default, or ``--scheduler tcp://host:8786``) and writes each run's reduced outputs into the
store as the results arrive; ``plot`` draws the study's figures from the store. docs/studies.md
describes the file, the store and running on a cluster.
"""
from .study_file import StudyError, load_study
from .expand import expand_study
from .store import Store
from .runner import run_study
from .summary import summarise

__all__ = ["StudyError", "load_study", "expand_study", "Store", "run_study", "summarise"]
