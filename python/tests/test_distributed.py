"""breakshot.distributed on a local Dask cluster of worker processes on
127.0.0.1: results identical to one machine, however the work is split,
and when a worker is killed mid-run."""

import json
import os
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import breakshot
import breakshot.distributed as bd




@pytest.fixture(scope="module")
def client():
    c = bd.local_client(2)
    yield c
    c.close()


def cli_match(run_cli, *args):
    r = run_cli("match", *args)
    assert r.returncode == 0, r.stderr
    return r.stdout


MATCH = dict(game="nine_ball", players=("baseline", "baseline"), games=12, seed=5,
             noise="tournament")
MATCH_ARGS = ["--game", "nine_ball", "--players", "baseline,baseline", "--games", "12",
              "--seed", "5", "--noise", "tournament"]


def test_workers_report_the_clients_build(client):
    found = bd.check_workers(client)
    assert len(found) == 2
    assert set(found.values()) == {bd.identity()}
    assert bd.identity()[0] == breakshot.__version__


def test_match_equals_the_command_however_split(client, run_cli):
    expected = cli_match(run_cli, *MATCH_ARGS)
    for chunk in (1, 5, 12):
        assert bd.match_json(client, chunk=chunk, progress=False, **MATCH) == expected, chunk
    assert bd.match(client, progress=False, **MATCH) == json.loads(expected)


def test_snooker_match_equals_the_command(client, run_cli):
    expected = cli_match(run_cli, "--game", "snooker", "--players", "baseline,baseline",
                         "--games", "2", "--seed", "3", "--noise", "tournament")
    got = bd.match_json(client, "snooker", ("baseline", "baseline"), games=2, seed=3,
                        noise="tournament", chunk=1, progress=False)
    assert got == expected


def test_first_game_equals_the_command(client, run_cli):
    expected = cli_match(run_cli, *MATCH_ARGS[:4], "--games", "4", "--first-game", "7",
                         *MATCH_ARGS[6:])
    got = bd.match_json(client, **dict(MATCH, games=4), first_game=7, chunk=3, progress=False)
    assert got == expected


def test_physics_choice_equals_the_command(client, run_cli):
    expected = cli_match(run_cli, *MATCH_ARGS[:4], "--games", "3", *MATCH_ARGS[6:],
                         "--cushion-model", "mathavan_2010", "--ball-ball-friction", "tpb3")
    assert '"physics"' in expected
    physics = breakshot.physics_of("mathavan_2010", ball_ball_friction="tpb3")
    got = bd.match_json(client, **dict(MATCH, games=3), physics=physics, chunk=1,
                        progress=False)
    assert got == expected


def test_records_are_the_commands_files(client, run_cli, tmp_path):
    cli_match(run_cli, *MATCH_ARGS[:4], "--games", "5", *MATCH_ARGS[6:],
              "--records", tmp_path / "cli")
    bd.match_json(client, **dict(MATCH, games=5), records=tmp_path / "dask", chunk=2,
                  progress=False)
    cli_files = sorted(p.name for p in (tmp_path / "cli").iterdir())
    assert cli_files == [f"game-{g:04d}.json" for g in range(1, 6)]
    assert sorted(p.name for p in (tmp_path / "dask").iterdir()) == cli_files
    for name in cli_files:
        assert (tmp_path / "dask" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes()
    assert run_cli("replay", tmp_path / "dask" / cli_files[-1]).returncode == 0


def test_ladder_rows_are_the_pairs_matches(client):
    levels = ["baseline", "beginner", "amateur"]
    table = bd.ladder(client, "nine_ball", levels, games=3, seed=2, progress=False)
    assert [r["players"] for r in table["rows"]] == [levels[:2], levels[1:]]
    for row in table["rows"]:
        alone = breakshot.match("nine_ball", row["players"], games=3, seed=2)
        assert row["summary"] == alone
        assert row["won"] == [p["games_won"] for p in alone["players"]]


def test_shot_map_equals_pot_map(client):
    # Player 0 (solids) has cleared its group: the 8 is its ball.
    position = {"game": "eight_ball", "balls": {0: (0.6, 0.6), 8: (2.2, 1.0), 12: (1.6, 0.9)},
                "groups": ["solids", "stripes"]}
    args = dict(xs=[0.8, 1.4, 1.9], ys=[0.4, 0.9], samples=8, seed=3)
    local = breakshot.pot_map(position, 8, "top_right", "club", threads=1, **args)
    for per in (1, 4):
        remote = bd.shot_map(client, position, 8, "top_right", "club", cells_per_task=per,
                             progress=False, **args)
        same_maps(remote, local)
    assert local.probability.max() > 0  # a map with something in it
    # A snooker game's own state travels to the workers whole.
    game = breakshot.Game("snooker", seed=4)
    player = breakshot.Player("club")
    while game.state.phase != "shot" or game.state.ball_in_hand != "none":
        game.apply(player.decide(game))
    red = next(n for n in range(1, 16) if game.state.on_table[n])
    args = dict(xs=[0.9, 1.8], ys=[0.5, 1.2], samples=4, candidates=2, seed=1)
    local = breakshot.pot_map(game, red, 0, "club", threads=1, **args)
    remote = bd.shot_map(client, game, red, 0, "club", cells_per_task=1, progress=False, **args)
    same_maps(remote, local)
    assert remote.position["state"] == local.position["state"]


def same_maps(a, b):
    for name in ("probability", "aims"):
        np.testing.assert_array_equal(np.ma.getmaskarray(getattr(a, name)),
                                      np.ma.getmaskarray(getattr(b, name)))
        np.testing.assert_array_equal(np.ma.getdata(getattr(a, name)),
                                      np.ma.getdata(getattr(b, name)))
    for name in ("valid", "shots", "plays"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name))
    assert a.kinds == b.kinds
    assert a.simulations == b.simulations


def test_sweep_gives_simulate_in_order(client, root):
    paths = sorted((root / "examples" / "pool").glob("*.json"))
    results = bd.sweep(client, paths, per_task=3, progress=False)
    assert [r.to_json() for r in results] == [breakshot.simulate(p).to_json() for p in paths]
    bad = {"physics": {"model": "ideal"}}
    with pytest.raises(breakshot.ScenarioError) as info:
        bd.sweep(client, [paths[0], bad])
    assert info.value.path == "scenarios[1].table"


def test_bad_arguments_name_what_is_wrong(client):
    with pytest.raises(ValueError, match='unknown player "nobody"'):
        bd.match(client, "nine_ball", ("baseline", "nobody"), games=1)
    with pytest.raises(ValueError, match="games"):
        bd.match(client, "nine_ball", ("baseline", "baseline"), games=0)
    with pytest.raises(ValueError, match="unknown game"):
        bd.match(client, "bowls", ("baseline", "baseline"), games=1)
    with pytest.raises(ValueError, match="snooker: 12ft"):
        bd.match(client, "snooker", ("baseline", "baseline"), games=1, table="9ft")
    with pytest.raises(ValueError, match="10ft"):
        bd.match(client, "nine_ball", ("baseline", "baseline"), games=1, table="10ft")


def test_a_worker_that_differs_is_refused(client):
    addr = sorted(client.scheduler_info()["workers"])[0]
    client.run(setattr, bd, "_identity_cache", (breakshot.__version__, "0000"), workers=[addr])
    try:
        with pytest.raises(bd.WorkerMismatch, match=addr):
            bd.check_workers(client)
        with pytest.raises(bd.WorkerMismatch):
            bd.match(client, **dict(MATCH, games=2), progress=False)
    finally:
        client.run(setattr, bd, "_identity_cache", None, workers=[addr])
    bd.check_workers(client)


def test_a_failed_game_names_its_index_and_seed():
    e = bd._as_match_error(RuntimeError("game 7 (seed 123): the rules refused the shot"),
                           ("nine_ball", ("club", "expert"), 5, "none", "9ft", None))
    assert isinstance(e, bd.MatchError)
    assert (e.game, e.seed) == (7, 123)
    assert e.command == ("breakshot match --game nine_ball --players club,expert --games 1 "
                         "--first-game 7 --seed 5 --noise none --table 9ft")
    assert "the rules refused the shot" in str(e) and e.command in str(e)


@pytest.mark.parametrize("physics, flags", [
    ("legacy", " --physics legacy"),
    ({"cushion_model": "mathavan_2010"}, " --cushion-model mathavan_2010"),
    (breakshot.physics_of("han_2005", "mathavan_2014", {"a": 0.02, "b": 0.1, "c": 1.5},
                          airborne=False, spinning_friction=0.03),
     " --cushion-model han_2005 --ball-ball-model mathavan_2014"
     " --ball-ball-friction 0.02,0.1,1.5 --airborne off --spinning-friction 0.03"),
    ({"ball_ball_friction": 0.06, "airborne": True},
     " --ball-ball-friction 0.06 --airborne on"),
])
def test_the_reproduce_command_carries_the_physics(physics, flags, run_cli, tmp_path):
    e = bd._as_match_error(RuntimeError("game 0 (seed 1): the rules refused the shot"),
                           ("nine_ball", ("baseline", "baseline"), 3, "tournament", "9ft",
                            physics))
    assert e.command == ("breakshot match --game nine_ball --players baseline,baseline "
                         "--games 1 --first-game 0 --seed 3 --noise tournament --table 9ft"
                         + flags)
    # The command plays the game the match played.
    r = run_cli(*e.command.split()[1:], "--records", tmp_path, check=True)
    record = json.loads((tmp_path / "game-0001.json").read_text())
    game = breakshot.Game("nine_ball", physics=physics)
    assert record["physics"] == json.loads(game._g.physics_json())
    assert r.stdout == breakshot.match_json("nine_ball", ["baseline", "baseline"], seed=3,
                                            noise="tournament", physics=physics)


def test_ladder_plays_the_games_table_with_the_physics_options(client, run_cli, root):
    # Snooker's table is implied by the game, as in match.
    table = bd.ladder(client, "snooker", ["baseline", "baseline"], games=1, seed=2,
                      progress=False)
    assert table["table"] == "12ft"
    assert table["rows"][0]["summary"] == breakshot.match("snooker", ["baseline", "baseline"],
                                                          games=1, seed=2)
    legacy = bd.ladder(client, "nine_ball", ["baseline", "baseline"], games=2, seed=2,
                       progress=False, physics="legacy")
    alone = breakshot.match("nine_ball", ["baseline", "baseline"], games=2, seed=2,
                            physics=breakshot.physics_of(preset="legacy"))
    assert legacy["rows"][0]["summary"] == alone
    assert alone["physics"]["cushion_model"] == "han_2005_v0"
    expected = cli_match(run_cli, "--game", "nine_ball", "--players", "baseline,baseline",
                         "--games", "2", "--seed", "2", "--noise", "none", "--physics", "legacy",
                         "--airborne", "on")
    r = subprocess.run([sys.executable, "-m", "breakshot.distributed", "ladder", "--workers",
                        "1", "--no-progress", "--game", "nine_ball", "--levels",
                        "baseline,baseline", "--games", "2", "--seed", "2", "--physics",
                        "legacy", "--airborne", "on"],
                       capture_output=True, text=True, cwd=root)
    assert r.returncode == 0, r.stderr
    assert json.loads(r.stdout)["rows"][0]["summary"] == json.loads(expected)
    r = subprocess.run([sys.executable, "-m", "breakshot.distributed", "ladder", "--workers",
                        "1", "--game", "snooker", "--levels", "baseline,baseline", "--games",
                        "1", "--physics", "modern"], capture_output=True, text=True, cwd=root)
    assert r.returncode == 2
    assert "--physics: unknown physics preset 'modern' (default or legacy)" in r.stderr


def test_killed_worker_loses_nothing(run_cli):
    # 60 games of about 50 ms each in one-game tasks: about 1.5 s on two
    # workers, long enough to kill one of them while both are playing.
    args = dict(game="nine_ball", players=("beginner", "amateur"), games=60, seed=11,
                noise="none")
    expected = cli_match(run_cli, "--game", "nine_ball", "--players", "beginner,amateur",
                         "--games", "60", "--seed", "11", "--noise", "none")
    with bd.local_client(2) as c:
        pids = c.run(os.getpid)
        victim = sorted(pids.values())[0]
        killed_at = []

        def kill_while_both_play():
            for _ in range(400):
                if sum(1 for tasks in c.processing().values() if tasks) == 2:
                    break
                time.sleep(0.01)
            os.kill(victim, signal.SIGKILL)
            killed_at.append(time.perf_counter())

        t = threading.Thread(target=kill_while_both_play)
        t.start()
        got = bd.match_json(c, chunk=1, progress=False, **args)
        ended_at = time.perf_counter()
        t.join()
    assert killed_at and killed_at[0] < ended_at  # killed mid-run
    for _ in range(100):  # the process is gone (its nanny reaps it)
        try:
            os.kill(victim, 0)
        except ProcessLookupError:
            break
        time.sleep(0.05)
    else:
        pytest.fail(f"worker process {victim} is still alive")
    assert got == expected


def test_command_prints_what_breakshot_match_prints(run_cli, root):
    expected = cli_match(run_cli, *MATCH_ARGS)
    r = subprocess.run([sys.executable, "-m", "breakshot.distributed", "match", "--workers", "2",
                        "--no-progress", *MATCH_ARGS], capture_output=True, text=True,
                       cwd=root)
    assert r.returncode == 0, r.stderr
    assert r.stdout == expected
    bad = subprocess.run([sys.executable, "-m", "breakshot.distributed", "match", "--workers",
                          "1", "--game", "nine_ball", "--players", "baseline,nobody", "--games",
                          "1", "--seed", "0", "--noise", "none"], capture_output=True, text=True)
    assert bad.returncode == 2
    assert 'unknown player "nobody"' in bad.stderr


def test_physics_options_take_the_spinning_friction():
    from types import SimpleNamespace

    def args(**kw):
        base = dict(physics=None, cushion_model=None, ball_ball_model=None,
                    ball_ball_friction=None, airborne=None, spinning_friction=None)
        base.update(kw)
        return SimpleNamespace(**base)

    assert bd._physics_args(args()) is None
    assert bd._physics_args(args(physics="legacy")) == "legacy"
    assert bd._physics_args(args(physics="legacy", airborne="on")) == \
        breakshot.physics_of(airborne=True, preset="legacy")
    with pytest.raises(ValueError, match="--physics: unknown physics preset"):
        bd._physics_args(args(physics="modern"))
    assert bd._physics_args(args(spinning_friction="legacy")) == \
        breakshot.physics_of(spinning_friction="legacy")
    assert bd._physics_args(args(spinning_friction="0.02"))["spinning_friction"] == 0.02
    for bad in ("slow", "0", "-1", "inf"):
        with pytest.raises(ValueError, match="--spinning-friction"):
            bd._physics_args(args(spinning_friction=bad))
