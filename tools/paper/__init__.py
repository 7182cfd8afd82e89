"""The paper's Figure 10 and Figure 11, reproduced: numbers, tables and the plot."""
