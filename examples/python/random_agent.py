"""A random agent playing breakshot.env.PoolEnv: prints each episode's
return (+1 won, -1 lost, 0 a draw or a truncated episode).

    .venv/bin/python examples/python/random_agent.py [--episodes 5] [--opponent baseline]
"""

import argparse

from breakshot.env import PoolEnv


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--game", default="nine_ball", help="nine_ball or eight_ball")
    ap.add_argument("--opponent", default="baseline", help="a name of breakshot.players()")
    ap.add_argument("--episodes", type=int, default=5)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()

    env = PoolEnv(game=args.game, opponent=args.opponent, seed=args.seed)
    env.action_space.seed(args.seed)
    obs, info = env.reset(seed=args.seed)
    for episode in range(args.episodes):
        total, steps = 0.0, 0
        while True:
            obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
            total += reward
            steps += 1
            if terminated or truncated:
                break
        how = "over" if terminated else "truncated"
        print(f"episode {episode}: return {total:+.1f} after {steps} steps ({how}; "
              f"{env.game.result or 'no result'})")
        obs, info = env.reset()
    env.close()


if __name__ == "__main__":
    main()
