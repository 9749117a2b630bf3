% SPDX-License-Identifier: MIT
function opts = hyst_options(args, opts, caller)
% HYST_OPTIONS  Name/value pairs in ARGS over the defaults OPTS (a struct).
% An unknown name, or a name without a value, raises hyst:usage.
  if mod(numel(args), 2) ~= 0
    error('hyst:usage', '%s: options come as name/value pairs', caller);
  end
  for k = 1:2:numel(args)
    name = args{k};
    if ~ischar(name) || ~isfield(opts, lower(name))
      error('hyst:usage', '%s: unknown option ''%s'' (known: %s)', caller, ...
            num2str(name), strjoin(fieldnames(opts)', ', '));
    end
    opts.(lower(name)) = args{k + 1};
  end
end
