// The lab's form fields: a labelled row, and a number field that checks
// what is typed before it changes the scenario.
//
// form: {errors, showErrors(), fail(message)}: errors maps a field's label
// to its problem (the lab shows the first); fail reports an edit the
// scenario refused.

import { el, errText } from './lab-dom.js';

export function row(label, control, unit) {
  return el('label', { class: 'bs-lab-row' }, el('span', { class: 'bs-lab-rowlabel', text: label }), control,
    el('span', { class: 'bs-lab-unit', text: unit || '' }));
}

// A text field for a number. On change: blank gives undefined (an error when
// `required`), a number is passed to onSet(v), anything else is an error.
export function numField(form, { value, placeholder = '', label, required = false, onSet, cls = '' }) {
  const inp = el('input', {
    type: 'text', inputmode: 'decimal', spellcheck: 'false', autocomplete: 'off',
    class: `bs-num ${cls}`, value: value == null ? '' : String(value),
    placeholder: placeholder === '' ? '' : String(placeholder), 'aria-label': label, title: label,
  });
  inp.addEventListener('change', () => {
    const s = inp.value.trim();
    let v;
    if (s === '') {
      if (required) { setFieldError(form, inp, label, 'a number is needed'); return; }
      v = undefined;
    } else {
      v = Number(s);
      if (s.length === 0 || !Number.isFinite(v)) { setFieldError(form, inp, label, `"${s}" is not a number`); return; }
    }
    clearFieldError(form, inp, label);
    try { onSet(v); } catch (e) { form.fail(errText(e)); }
  });
  return inp;
}

function setFieldError(form, inp, label, msg) {
  inp.classList.add('bs-invalid');
  form.errors.set(label, msg);
  form.showErrors();
}

function clearFieldError(form, inp, label) {
  inp.classList.remove('bs-invalid');
  if (form.errors.delete(label)) form.showErrors();
}
