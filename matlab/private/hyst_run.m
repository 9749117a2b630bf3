% SPDX-License-Identifier: MIT
function [out, status, tp_count, inv_err] = hyst_run(command, model, in, args)
% HYST_RUN  What HYST_SIM (COMMAND 'sim') and HYST_INV ('inv') share: the
%   options, the model of either kind and one block call of the gateway
%   (hyst_mex COMMAND, or COMMAND_everett for the asymmetric kind). HYST_INV
%   also takes 'intervals' (the compensator tabulated as firmware runs it; 0:
%   exact, or solved for the asymmetric kind) and, for the asymmetric kind
%   with 'intervals', 'rows' (default: the library's HYST_EVERETT_INV_ROWS).
%   Table sizes out of the library's range are refused here
%   (HYST_TABLE_SIZES), before the gateway allocates anything. A model with
%   a creep term (fields creep_tau, creep_weight) runs it too, as 'hyst sim
%   --model' and 'hyst inv --model' do (the gateway's ctau, cweight); so does
%   one with a rate term (fields rate_tau, rate_weight: rtau, rweight).
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
    [intervals, rows] = hyst_table_sizes(opts.intervals, opts.rows, p.kind, caller, true);
  end
  creep = {p.creep_tau, p.creep_weight, p.rate_tau, p.rate_weight};
  if strcmp(p.kind, 'everett_grid') && strcmp(command, 'inv') && (intervals > 0 || ~isempty(opts.rows))
    error('hyst:usage', ['%s: kind everett_grid has no tabulated compensator (it solves each ' ...
                         'branch in closed form): no ''intervals'' or ''rows'''], caller);
  end
  if strcmp(p.kind, 'everett_grid')
    [out, status, tp_count] = hyst_mex([command '_grid'], p.knots, p.weights, p.y_lo, in, ...
                                       double(opts.capacity), double(opts.deadband), creep{:});
  elseif strcmp(p.kind, 'everett') && strcmp(command, 'inv')
    [out, status, tp_count, inv_err] = hyst_mex('inv_everett', p.degree, p.lo, p.hi, p.y_lo, ...
                                                p.terms, in, double(opts.capacity), ...
                                                double(opts.deadband), intervals, rows, creep{:});
  elseif strcmp(p.kind, 'everett')
    [out, status, tp_count] = hyst_mex('sim_everett', p.degree, p.lo, p.hi, p.y_lo, ...
                                       p.terms, in, double(opts.capacity), ...
                                       double(opts.deadband), creep{:});
  elseif strcmp(command, 'inv')
    [out, status, tp_count, inv_err] = hyst_mex(command, p.coeffs, p.lo, p.hi, in, ...
                                                double(opts.capacity), double(opts.deadband), ...
                                                intervals, creep{:});
  else
    [out, status, tp_count] = hyst_mex(command, p.coeffs, p.lo, p.hi, in, ...
                                       double(opts.capacity), double(opts.deadband), creep{:});
  end
end
