return QuantumRayTracing.Cli.CommandLine.Run(args);
