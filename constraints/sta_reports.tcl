# OpenSTA on the netlist prepared by scripts/sta_netlist.sh, against the SDC,
# with the memory macros' timing: the reports both synthesis flows read
# (scripts/synth.sh, scripts/synth_flat.sh). The caller sets lib (standard-cell
# liberty), out (the run's directory) and sdc before sourcing this file.
read_liberty $lib
read_liberty $out/mcadsw_ram.lib
read_verilog $out/mcadsw_engine_sta.v
link_design mcadsw_engine
read_sdc $sdc
report_checks -path_delay max -digits 3 -fields {fanout cap slew}
report_wns -digits 3
report_tns -digits 3
report_worst_slack -digits 3
report_checks -path_delay max -group_count 100000 -format end > $out/sta_endpoints.log
