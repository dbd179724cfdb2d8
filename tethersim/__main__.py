from tethersim.cli.main import main

raise SystemExit(main())
