// The ruling log under the table: one line per action, in the words of
// game-words.js's logLine (the engine's ruling, the winner, whose turn
// it is next where the engine gave no words), a shot's line with its replay and link buttons.
// Functions of the GameUI (game.js).

import { $ } from './game-dom.js';
import { logLine } from './game-words.js';

export function renderLog(ui) {
  const ol = $('ruling-log');
  ol.textContent = '';
  for (const e of ui.flow.log) ol.appendChild(logItem(ui, e));
  ol.scrollTop = ol.scrollHeight;
}

function span(className, text) {
  const s = document.createElement('span');
  s.className = className;
  s.textContent = text;
  return s;
}

function logItem(ui, e) {
  const li = document.createElement('li');
  li.className = `p${e.player}`;
  li.dataset.index = String(e.index);
  if (e.kind === 'shoot') {
    const b = document.createElement('button');
    b.type = 'button';
    b.className = 'small replay';
    b.textContent = 'replay';
    b.title = `replay shot ${e.index}`;
    b.dataset.index = String(e.index);
    b.addEventListener('click', () => ui.replay(e.index));
    li.appendChild(b);
    const l = document.createElement('button');
    l.type = 'button';
    l.className = 'small replay shot-link';
    l.textContent = 'link';
    l.title = `a link that opens this game and replays shot ${e.index + 1}`;
    l.dataset.index = String(e.index);
    l.addEventListener('click', () => ui.share(e.index));
    li.appendChild(l);
  }
  const line = logLine(e, ui.flow.players);
  li.appendChild(span('who', line.who));
  // The ruling's words name its fouls; a foul's are shown in the foul colour.
  li.appendChild(line.foul ? span('foul', `${line.text} `) : document.createTextNode(`${line.text} `));
  if (line.win) li.appendChild(span('win', `${line.win} `));
  if (line.next) li.appendChild(span('meta', line.next));
  return li;
}
