% SPDX-License-Identifier: MIT
function [out, status, tp_count] = hyst_run(command, model, in, args)
% HYST_RUN  What HYST_SIM (COMMAND 'sim') and HYST_INV ('inv') share: the
%   options, the model of either kind and one block call of the gateway
%   (hyst_mex COMMAND, or COMMAND_everett for the asymmetric kind).
  caller = ['hyst_' command];
  opts = hyst_options(args, struct('capacity', 2048, 'deadband', 0), caller);
  p = hyst_model_parts(model, caller);
  if strcmp(p.kind, 'everett')
    [out, status, tp_count] = hyst_mex([command '_everett'], p.degree, p.lo, p.hi, p.y_lo, ...
                                       p.terms, in, double(opts.capacity), double(opts.deadband));
  else
    [out, status, tp_count] = hyst_mex(command, p.coeffs, p.lo, p.hi, in, ...
                                       double(opts.capacity), double(opts.deadband));
  end
end
