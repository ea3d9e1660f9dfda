"""Make the example jsPsych experiment: a stimulus set, its web site, and the experiment in that site.

    python examples/web/make_experiment.py -o experiment-site/
    python3 -m http.server -d experiment-site/ 8000     # then open http://127.0.0.1:8000/experiment.html

Steps (each one a command you could type; docs/web-jspsych.md):

1. ``artificial-person stimuli DESIGN -o SET`` — unless ``SET`` already holds a set (its ``manifest.csv``);
   the design is ``examples/web/design.toml`` unless ``--design`` names another;
2. ``artificial-person web-export --stimuli SET --design DESIGN -o SITE`` (each stimulus's head made again
   from the design: identities too), or with ``-m MODEL`` instead of ``--design`` when one is given;
3. copy into ``SITE``: ``plugin-artificial-person.js`` and ``jspsych/`` (jsPsych 8 and its keyboard plugin)
   from the installed package (``engine/web/jspsych/``, ``engine/web/vendor/jspsych/``), and this folder's
   ``experiment.html`` and ``experiment.js`` (the jsPsych experiment), ``embed.html`` and ``head-in-frame.js``
   (a stimulus in an iframe, on the outer page's clock: the pattern for PsychoJS and other frameworks).

A failing step ends with its own one-line error and status; nothing else is printed but what was made.
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
from importlib import resources
from pathlib import Path

HERE = Path(__file__).resolve().parent
EXPERIMENT_FILES = ("experiment.html", "experiment.js", "embed.html", "head-in-frame.js")
PLUGIN = "plugin-artificial-person.js"


def artificial_person(*args: str | Path) -> None:
    """Run one ``artificial-person`` verb in this interpreter's environment; stop with its status if it fails."""
    done = subprocess.run([sys.executable, "-m", "engine", *map(str, args)], check=False)
    if done.returncode != 0:
        raise SystemExit(done.returncode)


def add_experiment(site: Path, experiment: Path = HERE) -> None:
    """Copy the plugin, jsPsych and the experiment's page and script into a ``web-export --stimuli`` site."""
    web = resources.files("engine.web")
    with resources.as_file(web / "jspsych" / PLUGIN) as plugin:
        shutil.copyfile(plugin, site / PLUGIN)
    vendored_copy = site / "jspsych"
    if vendored_copy.exists():
        shutil.rmtree(vendored_copy)
    with resources.as_file(web / "vendor" / "jspsych") as vendored:
        shutil.copytree(vendored, vendored_copy, ignore=shutil.ignore_patterns("README.md"))
    for name in EXPERIMENT_FILES:
        shutil.copyfile(experiment / name, site / name)


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    parser.add_argument("-o", "--output", type=Path, required=True, help="the site folder to make (SITE)")
    parser.add_argument("--set", type=Path, help="the stimulus set's folder (default: SITE-set); made if empty")
    parser.add_argument("--design", type=Path, default=HERE / "design.toml", help="the design of the set")
    parser.add_argument("-m", "--model", type=Path, help="the head (default: the shipped one)")
    args = parser.parse_args(argv)
    site = args.output
    stimulus_set = args.set or site.with_name(site.name + "-set")
    if not (stimulus_set / "manifest.csv").is_file():
        artificial_person("stimuli", args.design, "-o", stimulus_set)
    heads = ["-m", args.model] if args.model else ["--design", args.design]     # the design's heads (identities)
    artificial_person("web-export", *heads, "--stimuli", stimulus_set, "-o", site)
    add_experiment(site)
    print(f"the experiment is {site / 'experiment.html'}: serve {site} (python3 -m http.server -d {site}) "
          "and open experiment.html")


if __name__ == "__main__":
    main()
