"""output/plots"""
