from pantarhei.bridge.cli import entry

entry()
