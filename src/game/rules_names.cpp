// Names of the game enums, as used in records, and the fouls in words, as
// rulings say them.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "breakshot/game.hpp"

namespace breakshot {

namespace {

template <class E, std::size_t N>
std::optional<E> parse(std::string_view s, const std::array<std::string_view, N>& names) {
  for (std::size_t i = 0; i < N; ++i) {
    if (names[i] == s) return static_cast<E>(i);
  }
  return std::nullopt;
}

constexpr std::array<std::string_view, 5> kGameNames{"eight_ball", "nine_ball", "snooker",
                                                     "three_cushion", "ten_ball"};
constexpr std::array<std::string_view, 3> kGroupNames{"none", "solids", "stripes"};
constexpr std::array<std::string_view, 7> kPhaseNames{
    "break_shot", "shot", "push_out_choice", "illegal_break_choice", "eight_on_break_choice",
    "game_over", "foul_choice"};
constexpr std::array<std::string_view, 4> kBallInHandNames{"none", "kitchen", "anywhere", "d"};
constexpr std::array<std::string_view, 10> kChoiceNames{
    "shoot",   "pass_back",      "accept_table",  "rerack_and_break", "rerack_opponent_breaks",
    "respot_eight", "play_on", "offender_again", "replace_balls", "concede"};
constexpr std::array<std::string_view, 12> kFoulNames{
    "scratch",           "no_contact",         "wrong_ball_first", "no_rail",
    "illegal_break",     "behind_head_string", "ball_off_table",   "in_off",
    "wrong_ball_potted", "free_ball_snooker",  "wrong_cue_ball",   "push_through"};

}  // namespace

std::string_view to_string(GameType g) { return kGameNames[static_cast<std::size_t>(g)]; }
std::optional<GameType> parse_game_type(std::string_view s) {
  return parse<GameType>(s, kGameNames);
}
std::vector<std::string> game_type_names() { return {kGameNames.begin(), kGameNames.end()}; }
std::string_view to_string(Group g) { return kGroupNames[static_cast<std::size_t>(g)]; }
std::optional<Group> parse_group(std::string_view s) { return parse<Group>(s, kGroupNames); }
std::string_view to_string(Phase p) { return kPhaseNames[static_cast<std::size_t>(p)]; }
std::optional<Phase> parse_phase(std::string_view s) { return parse<Phase>(s, kPhaseNames); }
std::string_view to_string(BallInHand b) { return kBallInHandNames[static_cast<std::size_t>(b)]; }
std::optional<BallInHand> parse_ball_in_hand(std::string_view s) {
  return parse<BallInHand>(s, kBallInHandNames);
}
std::string_view to_string(Choice c) { return kChoiceNames[static_cast<std::size_t>(c)]; }
std::optional<Choice> parse_choice(std::string_view s) { return parse<Choice>(s, kChoiceNames); }
std::string_view to_string(Foul f) { return kFoulNames[static_cast<std::size_t>(f)]; }

std::string_view foul_words(Foul f) {
  // The one place a foul is put in words: every ruling's text takes its
  // fouls from here (rules.cpp's fouls_in_words).
  switch (f) {
    case Foul::scratch:
      return "a scratch";
    case Foul::no_contact:
      return "no ball hit";
    case Foul::wrong_ball_first:
      return "the wrong ball hit first";
    case Foul::no_rail:
      return "no ball to a cushion after the contact";
    case Foul::illegal_break:
      return "an illegal break";
    case Foul::behind_head_string:
      return "a ball behind the head string hit first from the kitchen";
    case Foul::ball_off_table:
      return "a ball off the table";
    case Foul::in_off:
      return "an in-off";
    case Foul::wrong_ball_potted:
      return "a ball not on potted";
    case Foul::free_ball_snooker:
      return "a snooker behind the free ball";
    case Foul::wrong_cue_ball:
      return "the wrong cue ball played";
    case Foul::push_through:
      return "a push-through";
  }
  return "a foul";
}
std::optional<Foul> parse_foul(std::string_view s) { return parse<Foul>(s, kFoulNames); }

}  // namespace breakshot
