-- wrk script: GET /maps/willow/route between random room ids (uniform in
-- 1..78, fixed seed), as in benches/README.md ("HTTP" rows of the route section):
--   wrk -t1 -c32 -d8s --latency -s benches/route_pairs.lua http://127.0.0.1:PORT
math.randomseed(7)
request = function()
  local a = math.random(1, 78)
  local b = math.random(1, 78)
  return wrk.format("GET", "/maps/willow/route?from=" .. a .. "&to=" .. b)
end
