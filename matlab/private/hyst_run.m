% SPDX-License-Identifier: MIT
function [out, status, tp_count, inv_err] = hyst_run(command, model, in, args)
% HYST_RUN  What HYST_SIM (COMMAND 'sim') and HYST_INV ('inv') share: the
%   options, the model of any kind and one block call of the gateway
%   (hyst_mex COMMAND, or COMMAND_everett, COMMAND_grid, COMMAND_spline:
%   HYST_MODEL_ARGS). HYST_INV also takes 'intervals' (the compensator
%   tabulated as firmware runs it; 0: exact, or solved for the asymmetric
%   kind) and, for the asymmetric kind with 'intervals', 'rows' (default:
%   the library's HYST_EVERETT_INV_ROWS); kind everett_grid has no table
%   (HYST_SOLVED_COMPENSATOR): either refused.
%   Table sizes out of the library's range are refused here
%   (HYST_TABLE_SIZES), before the gateway allocates anything. A model with
%   a creep term (fields creep_tau, creep_weight) runs it too, as 'hyst sim
%   --model' and 'hyst inv --model' do (the gateway's ctau, cweight); so does
%   one with a rate term (fields rate_tau, rate_weight: rtau, rweight).
  caller = ['hyst_' command];
  inverse = strcmp(command, 'inv');
  defaults = struct('capacity', 2048, 'deadband', 0);
  if inverse
    defaults.intervals = 0;
    defaults.rows = [];
  end
  opts = hyst_options(args, defaults, caller);
  p = hyst_model_parts(model, caller);
  run = {in, double(opts.capacity), double(opts.deadband)};
  if inverse
    [intervals, rows] = hyst_table_sizes(opts.intervals, opts.rows, p.kind, caller, true);
    how = hyst_solved_compensator(p.kind);
    if ~isempty(how) && (intervals > 0 || ~isempty(opts.rows))
      error('hyst:usage', ['%s: kind %s has no tabulated compensator (it %s): no ' ...
                           '''intervals'' or ''rows'''], caller, p.kind, how);
    end
    if strcmp(p.kind, 'everett')
      run = [run, {intervals, rows}];
    elseif any(strcmp(p.kind, {'poly', 'spline'}))
      run = [run, {intervals}];
    end
  end
  [suffix, args] = hyst_model_args(p);
  creep = {p.creep_tau, p.creep_weight, p.rate_tau, p.rate_weight};
  if inverse  % inv_err: 0 for a compensator without a table
    [out, status, tp_count, inv_err] = hyst_mex([command suffix], args{:}, run{:}, creep{:});
  else
    [out, status, tp_count] = hyst_mex([command suffix], args{:}, run{:}, creep{:});
    inv_err = 0;
  end
end
