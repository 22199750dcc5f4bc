"""Chunks of a match (the groundwork of breakshot.distributed): games
first_game .. first_game + games - 1 played alone give one long match's
games, their summaries add up to that match's summary byte for byte, and
their records are the files `breakshot match --records` writes."""

from __future__ import annotations

import json
import re
import subprocess
import sys

import pytest

import breakshot
import breakshot._core as core


def chunk(game, players, first, games, seed=4, noise="tournament", table="9ft", records=False):
    return core.match_chunk(game, list(players), seed, noise, table, first, games, 1, records)


@pytest.mark.parametrize("game,players,n,chunks,order", [
    ("eight_ball", ("baseline", "baseline"), 9, [(0, 2), (2, 1), (3, 4), (7, 2)], [2, 0, 3, 1]),
    ("nine_ball", ("baseline", "beginner"), 4, [(0, 1), (1, 2), (3, 1)], [1, 2, 0]),
])
def test_chunks_add_up_to_one_match(game, players, n, chunks, order):
    whole = core.match_json(game, list(players), n, 4, "tournament", "9ft", None, 1)
    parts = [chunk(game, players, f, k)[0] for f, k in chunks]
    for (f, k), text in zip(chunks, parts):
        summary = json.loads(text)
        assert summary["games_played"] == k
        assert summary.get("first_game", 0) == f
        assert ("first_game" in summary) == (f != 0)
    assert core.add_match_summaries([parts[i] for i in order]) == whole
    # In pairs, each sum a summary text again.
    left = core.add_match_summaries([parts[order[0]], parts[order[1]]])
    right = core.add_match_summaries([parts[i] for i in order[2:]])
    assert core.add_match_summaries([right, left]) == whole


def test_chunk_records_are_the_cli_records(tmp_path, run_cli):
    run_cli("match", "--game", "nine_ball", "--players", "baseline,baseline", "--games", 5,
            "--seed", 4, "--noise", "tournament", "--records", tmp_path, check=True)
    got = {}
    for first, games in [(3, 2), (0, 3)]:
        summary, records = chunk("nine_ball", ("baseline", "baseline"), first, games,
                                 records=True)
        assert [g for g, _ in records] == list(range(first, first + games))
        got.update(records)
    assert sorted(p.name for p in tmp_path.iterdir()) == [core.record_file_name(g)
                                                           for g in range(5)]
    for g, text in got.items():
        assert (tmp_path / core.record_file_name(g)).read_text() == text
    # Without records, none come back.
    assert chunk("nine_ball", ("baseline", "baseline"), 1, 1)[1] == []


def test_first_game_equals_the_cli(tmp_path, run_cli):
    args = ("--game", "eight_ball", "--players", "baseline,baseline", "--games", 3, "--seed", 9,
            "--noise", "2x", "--table", "7ft", "--first-game", 4)
    r = run_cli("match", *args, "--records", tmp_path / "cli", check=True)
    text = breakshot.match_json("eight_ball", ("baseline", "baseline"), games=3, seed=9,
                                noise="2x", table="7ft", records=tmp_path / "py", first_game=4)
    assert text == r.stdout
    summary = breakshot.match("eight_ball", ("baseline", "baseline"), games=3, seed=9,
                              noise="2x", table="7ft", first_game=4)
    assert summary == json.loads(r.stdout)
    assert summary["first_game"] == 4
    names = sorted(p.name for p in (tmp_path / "cli").iterdir())
    assert names == ["game-0005.json", "game-0006.json", "game-0007.json"]
    for name in names:
        assert (tmp_path / "py" / name).read_text() == (tmp_path / "cli" / name).read_text()
    assert chunk("eight_ball", ("baseline", "baseline"), 4, 3, seed=9, noise="2x",
                 table="7ft")[0] == r.stdout


@pytest.mark.parametrize("jobs,threads", [(2, None), (0, None), (3, 1)])
def test_jobs_give_the_cli_summary_and_records(tmp_path, run_cli, jobs, threads):
    args = ("--game", "nine_ball", "--players", "baseline,beginner", "--games", 5, "--seed", 3,
            "--noise", "tournament", "--table", "8ft", "--jobs", 1)
    r = run_cli("match", *args, "--records", tmp_path / "cli", check=True)
    text = breakshot.match_json("nine_ball", ("baseline", "beginner"), games=5, seed=3,
                                noise="tournament", table="8ft", records=tmp_path / "py",
                                threads=threads, jobs=jobs)
    assert text == r.stdout
    names = sorted(p.name for p in (tmp_path / "cli").iterdir())
    assert len(names) == 5
    for name in names:
        assert (tmp_path / "py" / name).read_text() == (tmp_path / "cli" / name).read_text()


def test_bad_jobs_are_refused():
    for bad in (-1, 1.5, True, "2"):
        with pytest.raises(ValueError, match="jobs"):
            breakshot.match("nine_ball", ("baseline", "baseline"), jobs=bad)


def test_summed_chunks_equal_match_sum(tmp_path, run_cli):
    parts = [chunk("nine_ball", ("baseline", "baseline"), f, k)[0] for f, k in [(0, 1), (4, 2)]]
    for i, text in enumerate(parts):
        (tmp_path / f"{i}.json").write_text(text)
    r = run_cli("match-sum", tmp_path / "1.json", tmp_path / "0.json", check=True)
    assert r.stdout == core.add_match_summaries(parts)
    assert json.loads(r.stdout)["game_ranges"] == [{"first_game": 0, "games": 1},
                                                   {"first_game": 4, "games": 2}]


def test_add_match_summaries_names_the_bad_text():
    a = chunk("nine_ball", ("baseline", "baseline"), 0, 1)[0]
    b = chunk("nine_ball", ("baseline", "baseline"), 1, 1)[0]
    other = chunk("nine_ball", ("baseline", "baseline"), 2, 1, seed=5)[0]
    with pytest.raises(ValueError, match=r"^summaries\[2\]: \(document\): "):
        core.add_match_summaries([a, b, "{"])
    with pytest.raises(ValueError, match=r"^summaries\[1\]: games_played: missing"):
        core.add_match_summaries([a, '{"game": "nine_ball", "table_size": "9ft", '
                                     '"seed": "4", "noise": "none"}'])
    with pytest.raises(ValueError, match=r"^summaries\[2\]: .*seed: "):
        core.add_match_summaries([a, b, other])
    with pytest.raises(ValueError, match=r"^summaries\[1\]: .*first_game: the summaries overlap"):
        core.add_match_summaries([a, a])
    with pytest.raises(ValueError, match="no summaries"):
        core.add_match_summaries([])


def test_chunk_argument_errors():
    with pytest.raises(ValueError, match="first_game"):
        chunk("nine_ball", ("baseline", "baseline"), -1, 1)
    with pytest.raises(ValueError, match="first_game"):
        chunk("nine_ball", ("baseline", "baseline"), 2**31 - 2, 2)
    with pytest.raises(ValueError, match="games"):
        chunk("nine_ball", ("baseline", "baseline"), 0, 0)
    with pytest.raises(ValueError, match="first_game"):
        breakshot.match("nine_ball", ("baseline", "baseline"), first_game=-2)
    with pytest.raises(ValueError, match="unknown player"):
        chunk("nine_ball", ("baseline", "nobody"), 0, 1)


def test_record_file_name():
    assert core.record_file_name(0) == "game-0001.json"
    assert core.record_file_name(12344) == "game-12345.json"
    with pytest.raises(ValueError, match="game"):
        core.record_file_name(-1)


def test_determinism_hash_is_a_stable_digest():
    h = core.determinism_hash()
    assert re.fullmatch(r"[0-9a-f]{16}", h)
    assert core.determinism_hash() == h
    # Another process with the same build computes the same.
    out = subprocess.run([sys.executable, "-c",
                          "import breakshot._core as c; print(c.determinism_hash())"],
                         capture_output=True, text=True, check=True).stdout.strip()
    assert out == h
