-- A mixed load: cached preset images, uncached simulate+render posts, and bad requests (broken
-- JSON, a wrong type, an unknown preset, a bad parameter). Counts answers by status class, so a
-- soak can show zero 5xx. SCENE (a file with T_END_HERE in it) comes from the environment.
local template = io.open(os.getenv("SCENE")):read("*a")
local json = {["Content-Type"] = "application/json"}
local threads = {}

function setup(thread)
  table.insert(threads, thread)
  thread:set("seed", math.random(1, 2 ^ 30))
end

function init(args)
  math.randomseed(seed)
  ok, client_errors, server_errors = 0, 0, 0
end

function request()
  local r = math.random()
  if r < 0.6 then
    return wrk.format("GET", "/api/render?preset=paper&format=png")
  elseif r < 0.8 then
    local t_end = string.format("%.9f", 2 + math.random() * 10)
    return wrk.format("POST", "/api/render?format=png", json, (template:gsub("T_END_HERE", t_end)))
  elseif r < 0.85 then
    return wrk.format("POST", "/api/simulate", json, '{"model": {"R": 0.5, ')
  elseif r < 0.9 then
    return wrk.format("POST", "/api/simulate", json, (template:gsub("T_END_HERE", '"ten"')))
  elseif r < 0.95 then
    return wrk.format("GET", "/api/presets/no-such-preset")
  else
    return wrk.format("GET", "/api/render?preset=paper&width=-5")
  end
end

function response(status, headers, body)
  if status >= 500 then
    server_errors = server_errors + 1
  elseif status >= 400 then
    client_errors = client_errors + 1
  else
    ok = ok + 1
  end
end

function done(summary, latency, requests)
  local totals = {0, 0, 0}
  for _, t in ipairs(threads) do
    totals[1] = totals[1] + t:get("ok")
    totals[2] = totals[2] + t:get("client_errors")
    totals[3] = totals[3] + t:get("server_errors")
  end
  local e = summary.errors
  io.write(string.format(
    "RESULT requests=%d rps=%.1f p50_ms=%.2f p99_ms=%.2f max_ms=%.2f ok=%d 4xx=%d 5xx=%d " ..
    "errors_connect=%d errors_read=%d errors_write=%d errors_timeout=%d\n",
    summary.requests, summary.requests / (summary.duration / 1e6), latency:percentile(50) / 1000,
    latency:percentile(99) / 1000, latency.max / 1000, totals[1], totals[2], totals[3],
    e.connect, e.read, e.write, e.timeout))
end
