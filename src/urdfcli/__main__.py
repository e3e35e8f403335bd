from urdfcli.cli import main

main()
