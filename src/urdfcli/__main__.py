from urdfcli.cli import run

run()
