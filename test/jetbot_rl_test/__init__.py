"""jetbot_rl_test: helper modules shared by jetbot_rl's rostests (imported by them, never run)."""
