# SPDX-License-Identifier: BSD-3-Clause
"""Short runs of the paper's slider-crank models (Sec. 6.2) for the plot and view tests, written
by `clearjoint simulate` as a user would: the journal reaches the wall within 10 ms, so 30 ms
gives free flight, impacts and several contact scenarios in well under a second."""
import json
import pathlib
import shutil
import subprocess

SHORT_END_TIME = 0.03
SHORT_REPORT_STEP = 1e-4


def short_model(models_dir: pathlib.Path, name: str, end_time: float = SHORT_END_TIME,
                report_step: float = SHORT_REPORT_STEP) -> dict:
    with open(models_dir / name) as stream:
        model = json.load(stream)
    model["solver"]["end_time"] = end_time
    model["solver"]["report_step"] = report_step
    return model


def write_run(cli: pathlib.Path, model: dict, folder: pathlib.Path, keep_model: bool = True) -> pathlib.Path:
    """Run `clearjoint simulate` on `model` into `folder`; with keep_model, the model is copied
    in as model.json (where clearjoint plot and view look for it)."""
    model_path = folder.parent / (folder.name + "-model.json")
    model_path.write_text(json.dumps(model))
    subprocess.run([str(cli), "simulate", str(model_path), "--out", str(folder)], check=True,
                   stdout=subprocess.DEVNULL)
    if keep_model:
        shutil.copy(model_path, folder / "model.json")
    return folder
