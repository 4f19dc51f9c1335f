"""Request -> ScenePlan: the offline planner (knowledge base as data files) and the LLM planner."""
