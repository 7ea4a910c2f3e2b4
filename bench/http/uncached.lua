-- POST of the paper scene with a t_end of its own per request: nothing comes from the cache, so
-- every request is a simulation (and a render). PATH_AND_QUERY and SCENE (a file with T_END_HERE in it)
-- come from the environment.
dofile("bench/http/report.lua")

local template = io.open(os.getenv("SCENE")):read("*a")
local path = os.getenv("PATH_AND_QUERY")
local headers = {["Content-Type"] = "application/json"}

function setup(thread)
  thread:set("seed", math.random(1, 2 ^ 30))
end

function init(args)
  math.randomseed(seed)
end

function request()
  local t_end = string.format("%.9f", 10 + math.random() * 10)
  return wrk.format("POST", path, headers, (template:gsub("T_END_HERE", t_end)))
end
