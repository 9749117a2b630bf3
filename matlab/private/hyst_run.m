% SPDX-License-Identifier: MIT
function [out, status, tp_count, inv_err] = hyst_run(command, model, in, args)
% HYST_RUN  What HYST_SIM (COMMAND 'sim') and HYST_INV ('inv') share: the
%   options, the model of either kind and one block call of the gateway
%   (hyst_mex COMMAND, or COMMAND_everett for the asymmetric kind). HYST_INV
%   also takes 'intervals' (the compensator tabulated as firmware runs it; 0:
%   exact, or solved for the asymmetric kind) and, for the asymmetric kind
%   with 'intervals', 'rows' (default: the library's HYST_EVERETT_INV_ROWS).
%   Table sizes out of the library's range are refused here, before the
%   gateway allocates anything.
  caller = ['hyst_' command];
  defaults = struct('capacity', 2048, 'deadband', 0);
  if strcmp(command, 'inv')
    defaults.intervals = 0;
    defaults.rows = [];
  end
  opts = hyst_options(args, defaults, caller);
  p = hyst_model_parts(model, caller);
  inv_err = 0;
  if strcmp(command, 'inv')
    rows = table_sizes(opts, p.kind, caller);
  end
  if strcmp(p.kind, 'everett') && strcmp(command, 'inv')
    [out, status, tp_count, inv_err] = hyst_mex('inv_everett', p.degree, p.lo, p.hi, p.y_lo, ...
                                                p.terms, in, double(opts.capacity), ...
                                                double(opts.deadband), double(opts.intervals), rows);
  elseif strcmp(p.kind, 'everett')
    [out, status, tp_count] = hyst_mex('sim_everett', p.degree, p.lo, p.hi, p.y_lo, ...
                                       p.terms, in, double(opts.capacity), double(opts.deadband));
  elseif strcmp(command, 'inv')
    [out, status, tp_count, inv_err] = hyst_mex(command, p.coeffs, p.lo, p.hi, in, ...
                                                double(opts.capacity), double(opts.deadband), ...
                                                double(opts.intervals));
  else
    [out, status, tp_count] = hyst_mex(command, p.coeffs, p.lo, p.hi, in, ...
                                       double(opts.capacity), double(opts.deadband));
  end
end

function rows = table_sizes(opts, kind, caller)
% The options 'intervals' (0, or 1..2^20) and 'rows' (3..4096, the asymmetric
% kind's tabulated compensator only) checked; ROWS what the gateway takes.
  max_intervals = 2^20;
  if ~is_whole(opts.intervals) || opts.intervals < 0 || opts.intervals > max_intervals
    error('hyst:usage', ['%s: ''intervals'' must be a whole number in 1..%d (the table''s ' ...
                         'intervals), or 0 for the exact compensator'], caller, max_intervals);
  end
  if ~isempty(opts.rows)
    if ~strcmp(kind, 'everett')
      error('hyst:usage', ['%s: ''rows'' belongs to the asymmetric kind''s tabulated ' ...
                           'compensator; a polynomial f0''s table has intervals only'], caller);
    end
    if opts.intervals == 0
      error('hyst:usage', ['%s: ''rows'' needs ''intervals'' (1..%d): without it the ' ...
                           'compensator is solved, not tabulated'], caller, max_intervals);
    end
    if ~is_whole(opts.rows) || opts.rows < 3 || opts.rows > 4096
      config = hyst_mex('config');
      error('hyst:usage', '%s: ''rows'' must be a whole number in 3..4096 (default %d)', ...
            caller, config.everett_inv_rows);
    end
    rows = double(opts.rows);
  else
    config = hyst_mex('config');      % the library's HYST_EVERETT_INV_ROWS
    rows = config.everett_inv_rows;
  end
end

function ok = is_whole(v)
  ok = isnumeric(v) && isreal(v) && isscalar(v) && isfinite(v) && v == floor(v);
end
