// The game tab's one DOM helper: an element by id.

export function $(id) { return document.getElementById(id); }
