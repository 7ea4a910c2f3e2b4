-- GET of one preset's image: after the first request every answer comes from the cache.
dofile("bench/http/report.lua")
