"""``study-analyse`` on data written here: Wagner's Hu against a hand-computed example, the intervals against
published values, the measures a fixed policy implies, the files of every host, and bad input.

The hand-computed example, from Wagner's (1993) definition, Hu = a² / (b · c) and pc = (b / N)(c / N) (a: the
hits of a category, b: its stimuli, c: the uses of its response, N: all judgments). One judge, twelve
stimuli, four answers:

===========  =====  ===  ====  =====  ===
stimulus      happy  sad  fear  other  b
===========  =====  ===  ====  =====  ===
happy           3     1    0     0     4
sad             1     2    1     0     4
fear            0     0    2     2     4
c               4     3    3     2    N=12
===========  =====  ===  ====  =====  ===

Hu(happy) = 3²/(4·4) = 9/16 = 0.5625, pc = (4/12)(4/12) = 1/9; Hu(sad) = 2²/(4·3) = 1/3, pc = (4/12)(3/12) =
1/12; Hu(fear) = 2²/(4·3) = 1/3, pc = 1/12. The hit rates are 3/4, 1/2 and 1/2: fear's and sad's are equal
and so are their Hu, though fear's misses went to "other" and sad's to two emotions.
"""

from __future__ import annotations

import csv
import hashlib
import io
from pathlib import Path

import pytest

from engine.study.analysis import analyse
from engine.study.columns import columns_for
from engine.study.measures import chance_proportion, hu_table, newcombe, paired_t, unbiased_hit_rate, wilson
from engine.study.results import ResultsError, read_results, read_results_text
from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error, run

COLUMNS, _ = columns_for(["intensity", "naturalness"], ["expression"])
EXAMPLE = [("happy", "happy")] * 3 + [("happy", "sad")] + [("sad", "happy"), ("sad", "sad"), ("sad", "sad"),
                                                           ("sad", "fear")] + \
          [("fear", "fear")] * 2 + [("fear", "other")] * 2


def results_text(trials: list[dict], study_id: str = "0123456789abcdef", manifest: str = "ab" * 32,
                 columns: list[str] = COLUMNS) -> str:
    """A results CSV as the browser writes it (the rows' unnamed columns left empty)."""
    out = io.StringIO()
    writer = csv.DictWriter(out, columns, extrasaction="ignore", lineterminator="\r\n")
    writer.writeheader()
    for number, trial in enumerate(trials, start=1):
        row = {"study": "demo", "study_id": study_id, "set_manifest_sha256": manifest, "trial": number,
               "phase": "test", "source": "synthetic", "presentation": "static", "rt": 800, "participant": "1",
               "stimulus": f"s{number:03d}", **trial}
        writer.writerow(row)
    return out.getvalue()


def judge(pairs: list[tuple[str, str]], participant: str = "1", **extra) -> list[dict]:
    return [{"participant": participant, "intended": i, "response": r, "expression": i.capitalize(), **extra}
            for i, r in pairs]


def test_hu_and_pc_of_the_hand_computed_example():
    rows, columns = ["happy", "sad", "fear"], ["happy", "sad", "fear", "other"]
    matrix = [[3, 1, 0, 0], [1, 2, 1, 0], [0, 0, 2, 2]]
    table = hu_table(matrix, rows, columns)
    assert table["happy"]["hu"] == pytest.approx(9 / 16) and table["happy"]["pc"] == pytest.approx(1 / 9)
    assert table["sad"]["hu"] == pytest.approx(1 / 3) and table["sad"]["pc"] == pytest.approx(1 / 12)
    assert table["fear"]["hu"] == pytest.approx(1 / 3) and table["fear"]["pc"] == pytest.approx(1 / 12)
    assert [table[e]["hit_rate"] for e in rows] == [0.75, 0.5, 0.5]
    assert unbiased_hit_rate(0, 4, 0) == 0.0 and chance_proportion(4, 0, 12) == 0.0


def test_the_example_read_from_a_results_file_gives_the_same_numbers():
    analysis = analyse(read_results_text(results_text(judge(EXAMPLE)), "r.csv"))
    hu = {row["emotion"]: row for row in analysis.hu}
    assert hu["happy"]["hu"] == pytest.approx(0.5625) and hu["happy"]["pc"] == pytest.approx(1 / 9)
    assert hu["sad"]["hu"] == pytest.approx(1 / 3) and hu["fear"]["pc"] == pytest.approx(1 / 12)
    rows, matrix = analysis.confusion[("synthetic", "static")]
    assert rows == ["happy", "sad", "fear"] and analysis.responses == ["happy", "sad", "fear", "other"]
    assert matrix == [[3, 1, 0, 0], [1, 2, 1, 0], [0, 0, 2, 2]]
    overall = next(r for r in analysis.recognition if r["emotion"] == "all")
    assert (overall["hits"], overall["trials"]) == (7, 12)


def test_a_judge_who_always_says_happy_scores_the_share_of_happy_faces():
    """Wagner's reason for Hu: "happy" for everything has a hit rate of 1 for happy, but Hu = pc = b/N."""
    pairs = [(e, "happy") for e in ["happy"] * 2 + ["sad"] * 3 + ["fear"] * 3 + ["neutral"] * 2]
    analysis = analyse(read_results_text(results_text(judge(pairs)), "r.csv"))
    hu = {row["emotion"]: row for row in analysis.hu}
    assert hu["happy"]["hit_rate"] == 1.0
    assert hu["happy"]["hu"] == pytest.approx(2 / 10) and hu["happy"]["pc"] == pytest.approx(2 / 10)
    assert all(hu[e]["hu"] == 0.0 and hu[e]["responses"] == 0 for e in ("sad", "fear", "neutral"))


def test_intervals_match_newcombes_published_examples():
    """Newcombe (1998), Statistics in Medicine 17: 857-872 and 873-890: Wilson's interval of 81/263 is
    0.2553-0.3662; method 10 for 56/70 − 48/80 gives 0.0524-0.3339."""
    assert [round(x, 4) for x in wilson(81, 263)] == [0.2553, 0.3662]
    assert [round(x, 4) for x in newcombe(48, 80, 56, 70)] == [0.2, 0.0524, 0.3339]


def test_the_paired_t_test_is_scipys():
    from scipy.stats import ttest_rel

    a, b = [0.2, 0.4, 0.35, 0.5], [0.5, 0.45, 0.7, 0.9]
    t, p, n = paired_t(a, b)
    expected = ttest_rel(b, a)
    assert (t, p, n) == (pytest.approx(expected.statistic), pytest.approx(expected.pvalue), 4)


def test_static_and_dynamic_and_synthetic_and_human_are_contrasted():
    trials = []
    for participant in ("1", "2"):
        trials += judge([("fear", "surprise")] * 3 + [("fear", "fear")], participant)                   # static 1/4
        trials += judge([("fear", "fear")] * 3 + [("fear", "surprise")], participant, presentation="dynamic")
        trials += judge([("fear", "fear")] * 4, participant, source="human")
    text = results_text(trials)
    analysis = analyse(read_results_text(text, "r.csv"))
    rows = {(r["contrast"], r["within"], r["emotion"], r["measure"]): r for r in analysis.contrasts}
    moving = rows[("dynamic − static", "synthetic", "fear", "hit_rate")]
    assert (moving["a_value"], moving["b_value"], moving["difference"]) == (0.25, 0.75, 0.5)
    assert moving["pooled_ci_low"] == pytest.approx(newcombe(2, 8, 6, 8)[1])
    assert moving["participants"] == 2 and moving["paired_mean"] == 0.5
    human = rows[("synthetic − human", "static", "fear", "hit_rate")]
    assert human["difference"] == -0.75
    assert ("dynamic − static", "synthetic", "fear", "hu") in rows


def test_ratings_are_averaged_per_emotion_and_condition():
    trials = [dict(t, rating_intensity=v, rating_naturalness=8 - v)
              for t, v in zip(judge([("happy", "happy")] * 3 + [("sad", "sad")]), [5, 6, 7, 2], strict=True)]
    analysis = analyse(read_results_text(results_text(trials), "r.csv"))
    means = {(r["scale"], r["emotion"]): r for r in analysis.ratings}
    assert means[("intensity", "happy")]["mean"] == 6.0 and means[("intensity", "happy")]["trials"] == 3
    assert means[("naturalness", "sad")]["mean"] == 6.0
    assert means[("intensity", "all")]["mean"] == pytest.approx(5.0)


def test_practice_does_not_count_and_inattentive_participants_are_left_out():
    trials = judge([("happy", "happy")], "1", phase="practice") + judge([("sad", "sad")], "1")
    trials += judge([("happy", "happy")], "1", phase="attention", expected="neutral")           # failed
    trials += judge([("sad", "happy")], "2") + judge([("happy", "neutral")], "2", phase="attention",
                                                     expected="neutral")
    results = read_results_text(results_text(trials), "r.csv")
    analysis = analyse(results)
    assert {t.participant for t in analysis.included} == {"2"} and len(analysis.included) == 1
    assert any("failing attention checks: 1" in note for note in analysis.notes)
    everyone = analyse(results, min_attention=0.0)
    assert {t.participant for t in everyone.included} == {"1", "2"}


def test_a_jatos_export_of_several_runs_and_a_cognition_export_are_read(tmp_path):
    """JATOS joins every run's CSV into one text; Cognition.run exports every jsPsych trial with its own columns."""
    joined = results_text(judge(EXAMPLE[:4], "7")) + "\n" + results_text(judge(EXAMPLE[4:], "8"))
    (tmp_path / "jatos.txt").write_text(joined)
    cognition = ["trial_type,trial_index,ap_row,page," + ",".join(COLUMNS),
                 "ap-page,0,page,consent" + "," * len(COLUMNS)]
    body = results_text(judge(EXAMPLE[:2], "9")).splitlines()[1:]
    cognition += [f"ap-study-trial,{k + 1},trial,," + line for k, line in enumerate(body)]
    (tmp_path / "cognition.csv").write_text("\n".join(cognition) + "\n")
    results = read_results([tmp_path / "jatos.txt", tmp_path / "cognition.csv"])
    assert sorted({t.participant for t in results.trials}) == ["7", "8", "9"]
    assert len(results.trials) == len(EXAMPLE) + 2


def test_a_trial_given_twice_counts_once_and_two_different_ones_are_refused(tmp_path):
    text = results_text(judge(EXAMPLE))
    (tmp_path / "a.csv").write_text(text)
    (tmp_path / "b.csv").write_text(text)
    results = read_results([tmp_path / "a.csv", tmp_path / "b.csv"])
    assert len(results.trials) == len(EXAMPLE) and results.duplicates == len(EXAMPLE)
    (tmp_path / "c.csv").write_text(results_text(judge([("happy", "sad"), *EXAMPLE[1:]])))
    with pytest.raises(ResultsError, match=r"c\.csv:2: participant 1's trial 1 is given twice, differently"):
        read_results([tmp_path / "a.csv", tmp_path / "c.csv"])


# -- bad input: one line naming the file, status 2 ---------------------------------------------------------------

def _analyse(tmp_path: Path, *files: Path, extra: tuple[str, ...] = ()) -> str:
    return assert_user_error(run_in_process("study-analyse", *files, *extra, "-o", tmp_path / "report"))


def test_results_from_another_study_are_refused(tmp_path):
    (tmp_path / "a.csv").write_text(results_text(judge(EXAMPLE)))
    (tmp_path / "b.csv").write_text(results_text(judge(EXAMPLE, "2"), study_id="fedcba9876543210"))
    line = _analyse(tmp_path, tmp_path / "a.csv", tmp_path / "b.csv")
    assert line.startswith(f"error: {tmp_path / 'b.csv'}:2: from another study") and "0123456789abcdef" in line
    assert not (tmp_path / "report").exists()


def test_a_file_missing_columns_is_refused(tmp_path):
    columns = [c for c in COLUMNS if c not in ("intended", "rt")]
    (tmp_path / "cut.csv").write_text(results_text(judge(EXAMPLE), columns=columns))
    line = _analyse(tmp_path, tmp_path / "cut.csv")
    assert line == f"error: {tmp_path / 'cut.csv'}:1: missing columns: intended, rt (not the data of " \
                   "`artificial-person study`, or cut by a spreadsheet)"


@pytest.mark.parametrize("text, message", [
    ("", "not the results of an Artificial Person study"),
    ("a,b,c\n1,2,3\n", "not the results of an Artificial Person study"),
    ('study,study_id,participant\n"open\n', "missing columns"),
    ("\x00\x01\x02", "not the results of an Artificial Person study"),
])
def test_files_that_are_not_results_are_refused(tmp_path, text, message):
    (tmp_path / "r.csv").write_text(text)
    assert message in _analyse(tmp_path, tmp_path / "r.csv")


def test_a_bad_cell_names_its_line(tmp_path):
    trials = judge(EXAMPLE)
    trials[4]["rt"] = "fast"
    (tmp_path / "r.csv").write_text(results_text(trials))
    assert _analyse(tmp_path, tmp_path / "r.csv") == f"error: {tmp_path / 'r.csv'}:6: rt: 'fast' is not a number " \
                                                     "within ±8.64e+07"


def test_a_set_whose_manifest_changed_since_the_study_was_built_is_refused(tmp_path):
    stimuli = tmp_path / "set"
    stimuli.mkdir()
    (stimuli / "manifest.csv").write_text("id,expression,file_png,sha256_png\n0001,Happy,0001.png,00\n")
    digest = hashlib.sha256((stimuli / "manifest.csv").read_bytes()).hexdigest()
    (tmp_path / "r.csv").write_text(results_text(judge(EXAMPLE), manifest=digest))
    done = run("study-analyse", tmp_path / "r.csv", "--set", stimuli, "--no-validate", "-o", tmp_path / "report")
    assert done.returncode == 0, done.stderr
    with (stimuli / "manifest.csv").open("a") as manifest:
        manifest.write("0002,Sad,0002.png,00\n")
    line = _analyse(tmp_path, tmp_path / "r.csv", extra=("--set", str(stimuli), "--no-validate"))
    assert line.startswith(f"error: {stimuli / 'manifest.csv'}: the set's manifest has changed since the study "
                           "was built")


def test_no_results_at_all_are_refused(tmp_path):
    (tmp_path / "empty").mkdir()
    assert _analyse(tmp_path, tmp_path / "empty") == f"error: {tmp_path / 'empty'}: holds no .csv or .txt results"
    (tmp_path / "practice.csv").write_text(results_text(judge(EXAMPLE, phase="practice")))
    assert "hold no test trial" in _analyse(tmp_path, tmp_path / "practice.csv")
    assert _analyse(tmp_path, tmp_path / "missing.csv") == f"error: {tmp_path / 'missing.csv'}: no such file"


def test_the_report_and_tables_are_written(tmp_path):
    trials = judge(EXAMPLE) + judge(EXAMPLE, presentation="dynamic") + judge(EXAMPLE, "2")
    (tmp_path / "r.csv").write_text(results_text(trials))
    done = run("study-analyse", tmp_path / "r.csv", "-o", tmp_path / "report")
    assert done.returncode == 0, done.stderr
    names = {p.name for p in (tmp_path / "report").iterdir()}
    assert {"report.html", "trials.csv", "participants.csv", "recognition.csv", "confusion.csv", "hu.csv",
            "contrasts.csv", "figures"} <= names
    page = (tmp_path / "report" / "report.html").read_text()
    assert "http://" not in page and "https://" not in page and page.count("data:image/png;base64,") == 3
    assert "synthetic static: recognised 14 of 24" in done.stdout
