% SPDX-License-Identifier: MIT
function hyst_model_save(file, model)
% HYST_MODEL_SAVE  Writes a model (f0 and its domain, or an E) to a text file.
%   HYST_MODEL_SAVE(FILE, MODEL) writes MODEL.coeffs (highest power first),
%   MODEL.lo and MODEL.hi (and MODEL.delay, samples, when it is not 0) in
%   the format hyst-model-text 1 (docs/matlab.md):
%
%     hyst-model-text 1
%     # ... comment lines
%     kind poly
%     lo 0
%     hi 40
%     coeffs -6.1875999999999998e-06 0.0011949 0.086443999999999993 0.58516999999999997
%
%   A model of kind 'everett' (HYST_SIM) is written with the keys kind
%   everett, lo, hi, y_lo, delay (when not 0), degree and terms. A model
%   with a creep term (fields creep_tau and creep_weight, 1 to 4 numbers
%   each) gets a comment line and the keys creep_tau and creep_weight after
%   its own, as the host tool writes them ('hyst fit --save').
%   Numbers are written with 17 significant digits, so HYST_MODEL_LOAD gives
%   the same doubles back. The file is written whole or not at all (a
%   temporary file beside FILE, renamed to it; on failure removed and an
%   error hyst:model_file raised). The file is not checked against the library:
%   HYST_SIM does that.
  p = hyst_model_parts(model, 'hyst_model_save');
  if ~ischar(file)
    error('hyst:usage', 'hyst_model_save: FILE is a file name');
  end
  hyst_model_check(p, 'hyst_model_save');
  if strcmp(p.kind, 'everett')
    about = ['# hyst model: asymmetric, branch function E on [lo, hi], terms e[i-1][j] of ' ...
             'w^i t^j for i = 1..degree, j = 0..degree-i (docs/matlab.md)\n'];
  else
    about = '# hyst model: f0 on [lo, hi], coefficients highest power first (docs/matlab.md)\n';
  end
  text = [sprintf(['hyst-model-text 1\n' about 'kind %s\n'], p.kind), ...
          sprintf('lo %.17g\nhi %.17g\n', p.lo, p.hi)];
  if strcmp(p.kind, 'everett')
    text = [text, sprintf('y_lo %.17g\n', p.y_lo)];
  end
  if p.delay ~= 0
    text = [text, sprintf('delay %d\n', p.delay)];
  end
  if strcmp(p.kind, 'everett')
    text = [text, sprintf('degree %d\nterms', p.degree), sprintf(' %.17g', p.terms)];
  else
    text = [text, 'coeffs', sprintf(' %.17g', p.coeffs)];
  end
  if ~isempty(p.creep_tau)
    text = [text, sprintf(['\n# creep: the output plus sum of creep_weight[k] s_k, s_k the ' ...
                           'input lagged with time constant creep_tau[k] samples (from lo at ' ...
                           'rest)\ncreep_tau']), sprintf(' %.17g', p.creep_tau), ...
            sprintf('\ncreep_weight'), sprintf(' %.17g', p.creep_weight)];
  end
  hyst_write_whole(file, [text sprintf('\n')], 'hyst_model_save');
end
