"""The oracle: the world side of the loop.

It turns qualitative descriptions (antecedents) into parameterizations of a
pour (`generative`), and parameterizations into the 9 expectation scores by
simulation. It knows nothing about rules.
"""
