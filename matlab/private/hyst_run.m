% SPDX-License-Identifier: MIT
function [out, status, tp_count, inv_err] = hyst_run(command, model, in, args)
% HYST_RUN  What HYST_SIM (COMMAND 'sim') and HYST_INV ('inv') share: the
%   options, the model of either kind and one block call of the gateway
%   (hyst_mex COMMAND, or COMMAND_everett for the asymmetric kind). HYST_INV
%   also takes 'intervals' (f0's compensator tabulated; 0: exact).
  caller = ['hyst_' command];
  defaults = struct('capacity', 2048, 'deadband', 0);
  if strcmp(command, 'inv')
    defaults.intervals = 0;
  end
  opts = hyst_options(args, defaults, caller);
  p = hyst_model_parts(model, caller);
  inv_err = 0;
  if strcmp(p.kind, 'everett')
    if isfield(opts, 'intervals') && opts.intervals ~= 0
      error('hyst:usage', ['%s: ''intervals'' tabulates a polynomial f0''s compensator; ' ...
                           'the asymmetric kind''s solves each branch'], caller);
    end
    [out, status, tp_count] = hyst_mex([command '_everett'], p.degree, p.lo, p.hi, p.y_lo, ...
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
