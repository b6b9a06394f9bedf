#!/usr/bin/env python3
"""check_openjd_template.py — what can be checked of the Open Job Description template without
an OpenJD runner: it is valid YAML of specification jobtemplate-2023-09, every {{Param.X}},
{{Task.Param.X}} and {{Task.File.X}} it uses is defined, the Render step runs vkpt --task with
--checkpoint and --resume and the Merge step, which depends on it, runs vkpt-merge; then both
steps' scripts run as a runner would run them (parameters substituted, one run per task) with
vkpt-ref on a tiny image, and the merge must succeed.

    check_openjd_template.py TEMPLATE VKPT_REF VKPT_MERGE SCENE WORK_DIR
"""
import os
import shutil
import re
import subprocess
import sys

import yaml  # Debian's python3-yaml

REFERENCE = re.compile(r"\{\{\s*([A-Za-z.]+)\s*\}\}")


def fail(message):
    print(f"check_openjd_template: {message}", file=sys.stderr)
    sys.exit(1)


def strings(node):
    if isinstance(node, str):
        yield node
    elif isinstance(node, dict):
        for value in node.values():
            yield from strings(value)
    elif isinstance(node, list):
        for value in node:
            yield from strings(value)


def check_references(template):
    params = {p["name"] for p in template["parameterDefinitions"]}
    for step in template["steps"]:
        space = step.get("parameterSpace", {}).get("taskParameterDefinitions", [])
        task_params = {p["name"] for p in space}
        files = {f["name"] for f in step["script"].get("embeddedFiles", [])}
        known = ({f"Param.{p}" for p in params} | {f"Task.Param.{p}" for p in task_params}
                 | {f"Task.File.{f}" for f in files})
        for text in strings(step):
            for name in REFERENCE.findall(text):
                if name not in known:
                    fail(f"step {step['name']} uses {{{{{name}}}}}, which is not defined")


def check_shape(template):
    if template.get("specificationVersion") != "jobtemplate-2023-09":
        fail("specificationVersion is not 'jobtemplate-2023-09'")
    steps = {s["name"]: s for s in template["steps"]}
    if set(steps) != {"Render", "Merge"}:
        fail(f"steps are {sorted(steps)}, expected Render and Merge")
    render = steps["Render"]["script"]["embeddedFiles"][0]["data"]
    for needle in ("--task", "--checkpoint", "--resume", "{{Param.Renderer}}"):
        if needle not in render:
            fail(f"the Render step's script does not pass {needle}")
    cancel = steps["Render"]["script"]["actions"]["onRun"].get("cancelation", {})
    if cancel.get("mode") != "NOTIFY_THEN_TERMINATE":
        fail("the Render step is not canceled with SIGTERM first (NOTIFY_THEN_TERMINATE)")
    if {"dependsOn": "Render"} not in steps["Merge"].get("dependencies", []):
        fail("the Merge step does not depend on Render")
    if "{{Param.Merger}}" not in steps["Merge"]["script"]["embeddedFiles"][0]["data"]:
        fail("the Merge step does not run vkpt-merge")


def substitute(text, values):
    return REFERENCE.sub(lambda m: str(values[m.group(1)]), text)


def run_step(step, values, work):
    """Runs one task of a step as a runner does: embedded files written, then onRun."""
    files = {}
    for f in step["script"].get("embeddedFiles", []):
        path = os.path.join(work, f"{step['name']}-{f['name']}.sh")
        with open(path, "w") as out:
            out.write(substitute(f["data"], values))
        files[f"Task.File.{f['name']}"] = path
    action = step["script"]["actions"]["onRun"]
    command = [action["command"]] + [substitute(a, {**values, **files}) for a in action["args"]]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"step {step['name']} ({values}) failed: {result.stderr.strip()}")


def main():
    template_path, vkpt_ref, vkpt_merge, scene, work = sys.argv[1:6]
    with open(template_path) as f:
        template = yaml.safe_load(f)
    check_shape(template)
    check_references(template)
    # A fresh folder: the template resumes a task from a part it finds there, and a part left
    # by an earlier run of another build is another render.
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    out = os.path.join(work, "out")
    values = {f"Param.{p['name']}": p.get("default") for p in template["parameterDefinitions"]}
    values.update({"Param.SceneFile": scene, "Param.OutputDir": out, "Param.Tasks": 3,
                   "Param.Spp": 6, "Param.Width": 8, "Param.Height": 8,
                   "Param.Renderer": vkpt_ref, "Param.Merger": vkpt_merge})
    steps = {s["name"]: s for s in template["steps"]}
    for task in range(1, values["Param.Tasks"] + 1):
        run_step(steps["Render"], {**values, "Task.Param.Task": task}, work)
    run_step(steps["Merge"], values, work)
    if not os.path.exists(os.path.join(out, "merged.exr")):
        fail("the Merge step wrote no merged.exr")
    print("check_openjd_template: passed")


if __name__ == "__main__":
    main()
